#!/usr/bin/env bash
# Quick start 2: install every package group, build everything with the test suite configured
# (scripts/build.sh), run the whole test suite through ctest (unit, GL on Mesa llvmpipe, CLI,
# valgrind), then the perf gate against the committed baseline (scripts/gate.sh), the sanitizer build's
# unit and CLI tests (scripts/sanitize.sh) and every fuzz target for 20 s (scripts/fuzz.sh). Each CLI
# test runs once: under the sanitizers where it may, else in the first ctest.
# --quick stops after ctest. Other arguments go to ctest, e.g.
# `bash scripts/test.sh --quick -L unit`.
# Usage: bash scripts/test.sh [--quick] [ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
quick=0
args=()
for a in "$@"; do
  if [ "$a" = --quick ]; then quick=1; else args+=("$a"); fi
done
# The whole run (no --quick, no ctest arguments) runs each unit and cli test once: the sanitizer step
# below builds the unit tests and runs them under ASan and UBSan, and runs the cli tests against
# build-asan/bench with the same checks. So the release build leaves the unit tests' programs out, and
# its ctest runs every other label and only the cli tests that never run under the sanitizers
# (tools/sanitizers/left-out.sh). With --quick or ctest arguments everything is built and ctest runs
# what it is asked, unit and cli tests included.
whole=0
[ "$quick" = 0 ] && [ ${#args[@]} -eq 0 ] && whole=1
if [ "$whole" = 1 ]; then
  bash "$root/scripts/build.sh" --without-unit-tests
else
  bash "$root/scripts/build.sh"
fi
# build.sh has just installed or found every package of the test group: the later steps need not ask
# dpkg again (50 queries, about 2.5 s of CPU and 11 s of wall under load, twice).
export SHADOWBENCH_DEPS_CHECKED=1
# Without a display, run under Xvfb so the GLFW backend is tested too (the EGL and OSMesa tests need
# no display either way).
wrap=()
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  wrap=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
# The second driver was installed above (scripts/install-deps.sh's test group): its tests may not skip.
export SHADOWBENCH_REQUIRE_DRIVERS=1
if [ "$whole" = 1 ]; then
  # The unit tests' programs were not built: ctest names each such program <target>_NOT_BUILT.
  unit_targets=$(awk '$2 == "unit" {print $1}' "$root/build/tests/TestLabels.txt" | paste -sd'|')
  args=(-LE '^unit$' -E "$(bash "$root/tools/sanitizers/covered-cli.sh" "$root/build")|^($unit_targets)_NOT_BUILT\$")
fi
(cd "$root/build" && "${wrap[@]}" ctest --output-on-failure --parallel "$(nproc)" "${args[@]}")
[ "$quick" = 1 ] && exit 0
# The gate runs beside the sanitizer build: its gating layers are exact (A counts work, B counts
# instructions under valgrind), so the build's load cannot change them, and the gate's processes run
# one at a time, leaving a core the build takes (about 2 minutes of CI). Layer C, wall time, is
# advisory here and says how noisy its rounds were. Its output is printed whole when both are done.
gate_log="$(mktemp)"
SHADOWBENCH_GATE_BUILD=0 bash "$root/scripts/gate.sh" >"$gate_log" 2>&1 &
gate_pid=$!
sanitize_rc=0
bash "$root/scripts/sanitize.sh" || sanitize_rc=$?
gate_rc=0
wait "$gate_pid" || gate_rc=$?
echo "---- perf gate (scripts/gate.sh, run beside the sanitizer build) ----"
cat "$gate_log"
rm -f "$gate_log"
[ "$gate_rc" = 0 ] || { echo "test.sh: the perf gate failed (exit $gate_rc)" >&2; exit "$gate_rc"; }
[ "$sanitize_rc" = 0 ] || { echo "test.sh: the sanitizer run failed (exit $sanitize_rc)" >&2; exit "$sanitize_rc"; }
bash "$root/scripts/fuzz.sh" 20
