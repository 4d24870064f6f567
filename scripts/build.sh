#!/usr/bin/env bash
# Installs what is missing (scripts/install-deps.sh), configures and builds shadowbench (Release) in
# build/ through the "release" preset of CMakePresets.json, so `cmake --preset release` by hand and this
# script configure the same folder the same way (Ninja, Release).
#   (no option)  everything: the packages of every group, the test suite configured
#                (SHADOWBENCH_BUILD_TESTS=ON) and every target built; what scripts/test.sh and the
#                perf gate use
#   --bench      the quick start (scripts/bench.sh): the bench group of packages and the bench
#                program alone. It leaves SHADOWBENCH_BUILD_TESTS as the folder has it, so after a
#                full build it neither drops the tests nor rebuilds anything but bench.
#   --without-unit-tests
#                as with no option, but the unit label's test programs are not built: scripts/test.sh's
#                whole run builds and runs them under the sanitizers instead (scripts/sanitize.sh),
#                so compiling them here too would only repeat about 150 s of CPU
# Other arguments go to cmake's configure step.
# Usage: bash scripts/build.sh [--bench | --without-unit-tests] [cmake configure arguments]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bench_only=0
without_unit=0
args=()
for a in "$@"; do
  case "$a" in
    --bench) bench_only=1 ;;
    --without-unit-tests) without_unit=1 ;;
    *) args+=("$a") ;;
  esac
done
if [ "$bench_only" = 1 ]; then
  bash "$root/scripts/install-deps.sh" bench
  targets=(--target bench sb_runtime_files)
else
  bash "$root/scripts/install-deps.sh" test
  args=(-DSHADOWBENCH_BUILD_TESTS=ON "${args[@]}")
  targets=()
fi
(cd "$root" && cmake --preset release "${args[@]}" >/dev/null)
if [ "$bench_only" = 0 ] && [ "$without_unit" = 1 ]; then
  # Every top-level target but the unit label's test programs: the programs, the files they read, the
  # manual page, and the test programs of the other labels (tests/CMakeLists.txt writes each test
  # target's label to build/tests/TestLabels.txt when it configures).
  targets=(--target bench handloop handshadow sb_runtime_files sb_man_and_completion)
  while read -r name label; do
    [ "$label" = unit ] || targets+=("$name")
  done <"$root/build/tests/TestLabels.txt"
fi
cmake --build "$root/build" --parallel "$(nproc)" "${targets[@]}"
