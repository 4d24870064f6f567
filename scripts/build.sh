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
# Other arguments go to cmake's configure step.
# Usage: bash scripts/build.sh [--bench] [cmake configure arguments]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bench_only=0
args=()
for a in "$@"; do
  if [ "$a" = --bench ]; then bench_only=1; else args+=("$a"); fi
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
cmake --build "$root/build" --parallel "$(nproc)" "${targets[@]}"
