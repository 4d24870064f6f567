#!/usr/bin/env bash
# Prints one ctest regular expression matching exactly the cli-label tests that scripts/sanitize.sh runs
# under the sanitizers (every cli test but those of tools/sanitizers/left-out.sh), for scripts/test.sh
# to leave out of its release ctest. It is compact so that it stays far below the size ctest's regular
# expressions allow (a few tens of KiB): a gtest suite all of whose tests (of any label) are covered is
# named once, "^Suite\.", any other covered test by its whole name.
# Usage: bash tools/sanitizers/covered-cli.sh BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build=${1:?usage: covered-cli.sh BUILD_DIR}
# shellcheck source=tools/sanitizers/left-out.sh
source "$here/left-out.sh"
names() { (cd "$build" && ctest -N "$@" | sed -n 's/^ *Test *#[0-9]*: //p'); }
all=$(names)
covered=$(names -L '^cli$' -E "$SB_SANITIZE_LEFT_OUT")
if [ -z "$covered" ]; then
  echo "covered-cli: no cli test found in $build (is it configured with the tests?)" >&2
  exit 1
fi
# First the covered names (marked 1), then every test (marked 0), one a line: a test's name may hold
# spaces (a parameter's comment). A suite is whole when each of its tests was marked covered.
{
  printf '%s\n' "$covered" | sed 's/^/1 /'
  printf '%s\n' "$all" | sed 's/^/0 /'
} | awk '
  function suite(n) { i = index(n, "."); return i ? substr(n, 1, i - 1) : n }
  function quote(s,   out, c, k) {
    out = ""
    for (k = 1; k <= length(s); ++k) {
      c = substr(s, k, 1)
      out = out (c ~ /[A-Za-z0-9_\/]/ ? c : "\\" c)
    }
    return out
  }
  { mark = substr($0, 1, 1); name = substr($0, 3) }
  mark == 1 { cov[name] = 1; next }
  {
    s = suite(name)
    total[s]++
    if (name in cov) { have[s]++; list[s, have[s]] = name }
  }
  END {
    re = ""
    for (s in have) {
      if (have[s] == total[s]) { re = re "|^" quote(s) "\\."; continue }
      for (k = 1; k <= have[s]; ++k) re = re "|^" quote(list[s, k]) "$"
    }
    print substr(re, 2)
  }'
