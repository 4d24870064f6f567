#!/usr/bin/env bash
# The perf gate as CI runs it (README "Gate a change"): builds if needed, then `bench ci` on the
# committed suite against the committed baseline (results/ci/): layer A (exact work, every
# configuration) and layer B (instructions per frame under valgrind, the suite's subset) gate; layer C
# (wall time: without a base build only the A/A control, what this machine could see) is printed and
# never fails here. The report goes to ci-out/ (report.md, report.json, the rows).
# The project's own CI (scripts/test.sh) and the workflow templates in tools/ci/ call this script.
# Usage: bash scripts/gate.sh [bench ci options], e.g. --base-bench /path/to/base/bench
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ ! -x "$root/build/bench" ] || [ "${SHADOWBENCH_GATE_BUILD:-1}" = 1 ]; then
  bash "$root/scripts/build.sh"
fi
cd "$root"
build/bench ci --out "${SHADOWBENCH_GATE_OUT:-ci-out}" --advisory C "$@"

# The second driver (bench --driver mesa-25.0.7; scripts/install-deps.sh driver installs it): layer A
# against that driver's own baseline, results/ci/baseline/mesa-25.0.7/ (about 45 s on 2 cores), then
# layer B of the configurations only that driver can run (the suite's "drivers": raytraced_vulkan,
# raytraced_soft_vulkan and raytraced_guided_vulkan, whose instructions no other run counts; four runs
# under valgrind, the first one twice as the A/A pair: 2 min 36 s on 2026-12-07 beside other builds). Not installed, it fails naming
# the install command. SHADOWBENCH_GATE_SECOND_DRIVER=0 leaves it out.
if [ "${SHADOWBENCH_GATE_SECOND_DRIVER:-1}" = 1 ]; then
  build/bench --driver mesa-25.0.7 ci --quick --out "${SHADOWBENCH_GATE_OUT:-ci-out}/mesa-25.0.7"
  build/bench --driver mesa-25.0.7 ci --layers B --driver-bound \
    --out "${SHADOWBENCH_GATE_OUT:-ci-out}/mesa-25.0.7-bound"
fi
