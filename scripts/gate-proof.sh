#!/usr/bin/env bash
# The perf gate's proof (results/ci/README.md): known regressions must be caught by the layer that
# should see them, and the same build against itself must pass. Writes one summary line per run to
# OUT/proof.csv (case, layer, verdict) and keeps every report under OUT/<case>/.
#   regressions: extra_fullscreen_pass, no_caster_culling, double_shadow_resolution (core/Injection.h),
#                each as head against the unmodified base (same binary, interleaved), all three layers;
#                and a driver-side slowdown: LP_NUM_THREADS=1 against 2.
#   A/A:         N times the same build against itself, all three layers (B on one configuration).
# Usage: bash scripts/gate-proof.sh [OUT (default out/gate-proof)] [N A/A runs (default 20)] [all|regressions|aa]
# SHADOWBENCH_BENCH and SHADOWBENCH_SUITE name another binary and suite (a copy, so that a rebuild
# during the proof cannot change what is measured).
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/out/gate-proof}"
aa="${2:-20}"
parts="${3:-all}"
bench="${SHADOWBENCH_BENCH:-$root/build/bench}"
suite="${SHADOWBENCH_SUITE:-$root/results/ci/suite.json}"
configs="none_aircraft,shadowmap_aircraft,volume_aircraft"
mkdir -p "$out"
[ -f "$out/proof.csv" ] || echo "case,layer,verdict" > "$out/proof.csv"

# Records the verdict of each layer of report.json in DIR as rows of case NAME.
record() {
  /usr/bin/python3 - "$1" "$2" "$out/proof.csv" <<'PY'
import json, sys
name, report, csv = sys.argv[1], sys.argv[2] + "/report.json", sys.argv[3]
try:
    doc = json.load(open(report))
    rows = [(name, l["name"].split(":")[0], l["verdict"]) for l in doc["layers"]]
except (OSError, ValueError, KeyError) as e:
    rows = [(name, "all", "ERROR " + str(e).replace(",", ";"))]
with open(csv, "a") as f:
    for r in rows: f.write(",".join(r) + "\n")
    print(" ".join(r[1] + "=" + r[2] for r in rows), "(" + name + ")")
PY
}

run_case() { # NAME, then bench ci options
  local name="$1"; shift
  "$bench" ci --suite "$suite" --configs "$configs" --out "$out/$name" "$@" > "$out/$name.log" 2>&1
  record "$name" "$out/$name"
}

if [ "$parts" != aa ]; then
  for inj in extra_fullscreen_pass no_caster_culling double_shadow_resolution; do
    run_case "$inj" --base-env SHADOWBENCH_INJECT= --head-env SHADOWBENCH_INJECT=$inj
  done
  run_case lp_threads_1_vs_2 --base-env LP_NUM_THREADS=2 --head-env LP_NUM_THREADS=1
fi
if [ "$parts" != regressions ]; then
  for i in $(seq 1 "$aa"); do
    run_case "aa_$i" --base-env SHADOWBENCH_PROOF=aa --layers A,C --seed "$i" --scheme random
    "$bench" ci --suite "$suite" --configs none_aircraft --base-env SHADOWBENCH_PROOF=aa --layers B \
      --out "$out/aa_b_$i" > "$out/aa_b_$i.log" 2>&1
    record "aa_b_$i" "$out/aa_b_$i"
  done
fi
echo "proof: $out/proof.csv"
