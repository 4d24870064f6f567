#!/usr/bin/env bash
# bench's shadow map against the hand-written one (bench/handwritten/handshadow/), side by side in one run:
# alternating processes A B B A A B ... (ROUNDS of each), `bench -t shadowmap:resolution=MAP` and
# `handshadow --map-size MAP` on the same scene, camera and size. Prints every round, both medians of the
# per-run medians (wall = submit + glFinish, and CPU submit) and the median ratio bench/hand with its
# min-max over the rounds. Then, if build/handloop exists, its in-process `none` comparison.
# On a shared machine the alternation lets noise hit both alike; read the ratio, not the milliseconds.
#
# Usage: scripts/handshadow.sh [ROUNDS=5] [MAP=2048] [extra scene options ...]
#   default scene: aircraft, horse.3ds from glmark2 (if installed), 1 instance, camera mid, 1024x1024
# Environment: BUILD=build directory (default build), FRAMES=frames per run (default 30),
#   HAND_ARGS=extra handshadow options (HAND_ARGS=--harness-targets: bench's RGBA16F visibility target and
#   DEPTH24_STENCIL8 in the hand program too, which leaves the technique's own cost in the ratio).
set -euo pipefail
# bench fixes glibc's heap trim and mmap thresholds at start (bench/BenchApp.cpp: heap trimming churn
# made frame times depend on heap layout); the hand program gets the same allocator through the tunables.
export GLIBC_TUNABLES="glibc.malloc.trim_threshold=268435456:glibc.malloc.mmap_threshold=33554432"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${BUILD:-$root/build}"
rounds="${1:-5}"
map="${2:-2048}"
shift $(($# > 2 ? 2 : $#)) || true
frames="${FRAMES:-30}"
if [ $# -gt 0 ]; then
    scene=("$@")
else
    scene=(--scene aircraft --instances 1 --camera mid --size 1024x1024)
    horse=/usr/share/glmark2/models/horse.3ds
    [ -f "$horse" ] && scene+=(--model "$horse")
fi
for b in bench handshadow; do
    [ -x "$build/$b" ] || { echo "handshadow.sh: $build/$b is missing (cmake --build $build --target $b)" >&2; exit 3; }
done

run_bench() {
    # --format csv: one row; the wall and cpu-submit medians are read from it by column name (quoted
    # fields hold commas, hence the csv module).
    "$build/bench" -t "shadowmap:resolution=$map" "${scene[@]}" --frames "$frames" --warmup 5 \
        --no-timer-check --format csv -q 2>/dev/null |
        python3 -c 'import csv, sys
row = list(csv.DictReader(sys.stdin))[-1]
print(row["wall_ms_median"], row["cpu_submit_ms_median"])'
}
run_hand() {
    "$build/handshadow" --map-size "$map" "${scene[@]}" --frames "$frames" --warmup 5 ${HAND_ARGS:-} |
        awk -F, '/^csv,handshadow/ { printf "%s %s\n", $7, $8 }'
}

bench_wall=() bench_cpu=() hand_wall=() hand_cpu=()
echo "round  bench wall / cpu submit (ms)   handshadow wall / cpu submit (ms)   ratio"
for ((r = 0; r < rounds; ++r)); do
    # A B B A: even rounds bench first, odd rounds hand first.
    if ((r % 2 == 0)); then b=$(run_bench); h=$(run_hand); else h=$(run_hand); b=$(run_bench); fi
    read -r bw bc <<<"$b"
    read -r hw hc <<<"$h"
    bench_wall+=("$bw") bench_cpu+=("$bc") hand_wall+=("$hw") hand_cpu+=("$hc")
    printf "%5d  %10.3f / %-10.3f          %10.3f / %-10.3f            %.3f\n" "$r" "$bw" "$bc" "$hw" "$hc" \
        "$(echo "$bw / $hw" | bc -l)"
done

median() { printf "%s\n" "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratios=()
for ((r = 0; r < rounds; ++r)); do ratios+=("$(echo "${bench_wall[r]} / ${hand_wall[r]}" | bc -l)"); done
echo "scene: ${scene[*]}, map ${map}^2, ${frames} frames per run, ${rounds} rounds each, handshadow ${HAND_ARGS:-(colour + depth targets)}"
printf "bench shadowmap  wall median %.3f ms  cpu submit median %.3f ms\n" "$(median "${bench_wall[@]}")" "$(median "${bench_cpu[@]}")"
printf "handshadow       wall median %.3f ms  cpu submit median %.3f ms\n" "$(median "${hand_wall[@]}")" "$(median "${hand_cpu[@]}")"
printf "ratio bench/hand (wall, per round)  median %.3f  min %.3f  max %.3f\n" "$(median "${ratios[@]}")" \
    "$(printf "%s\n" "${ratios[@]}" | sort -g | head -1)" "$(printf "%s\n" "${ratios[@]}" | sort -g | tail -1)"

if [ -x "$build/handloop" ]; then
    echo "--- handloop (none through the harness against a hand loop, in one process):"
    "$build/handloop" "${scene[@]}" --frames "$frames" | tail -3
fi
