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
