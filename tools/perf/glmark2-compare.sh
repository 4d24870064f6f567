#!/usr/bin/env bash
# glmark2's `shadow` scene against bench's `shadowmap` on the same frame (results/perf/horse.json), side by
# side in one run on one driver: alternating processes A B B A ... (K rounds of each), glmark2 off-screen
# under Xvfb and bench on EGL, both at the same size with a map of twice the size per side (glmark2's rule:
# its map is 2 x the canvas). Prints every round and the median ratio bench/glmark2 with its min-max.
# The written-up results and what each number means: results/perf/README.md.
#
# Frame times compared: glmark2 prints "FrameTime: X ms", its run's elapsed time over its frames (a mean,
# every frame ended by glFinish off-screen, the first frame's shader compiles included); bench's
# wall_ms_mean (submit + glFinish per frame, after --warmup frames, so no compile). On a shared machine
# only the ratio of one round means anything: the alternation lets load hit both alike.
set -euo pipefail

usage() {
    cat <<'EOF'
Usage: tools/perf/glmark2-compare.sh [options]

Alternates glmark2 -b shadow and bench -t shadowmap on the same frame and driver and prints each
round's frame times and the median ratio bench/glmark2.

Options:
  --rounds K        rounds (each runs both programs; even rounds glmark2 first) [5]
  --size N          canvas N x N for both; the map is 2N x 2N (glmark2's own rule) [1024]
  --driver NAME     system, mesa-25.0.7 or a Mesa prefix path, as bench --driver takes it [system]
  --duration S      seconds of each glmark2 run [5]
  --frames N        measured frames of each bench run (after 5 warm-up frames) [100]
  --build DIR       the build folder holding bench [build]
  --technique T     bench's technique and properties [shadowmap]; resolution=2N is appended
  --lighting R      bench's --lighting: fragment (shadowbench's image) or vertex (glmark2's model:
                    its horse is lit per vertex) [the scene's: fragment]
  -h, --help        this text

Exit codes: 0 done, 2 wrong input, 3 a tool, the model or the driver is missing, 1 a run failed.

Examples:
  tools/perf/glmark2-compare.sh --rounds 5                          # system Mesa, 1024^2, map 2048^2
  tools/perf/glmark2-compare.sh --rounds 5 --driver mesa-25.0.7     # both programs on Mesa 25.0.7
  tools/perf/glmark2-compare.sh --rounds 3 --size 512 --duration 3 --frames 50   # a quick look
  tools/perf/glmark2-compare.sh --build build-glmark --technique shadowmap:pcf=1   # another build, a knob
  tools/perf/glmark2-compare.sh --rounds 5 --lighting vertex        # bench lit per vertex, as glmark2 lights
EOF
}

die() { # die CODE MESSAGE
    echo "glmark2-compare: $2" >&2
    exit "$1"
}

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rounds=5 size=1024 driver=system duration=5 frames=100 build="${BUILD:-$root/build}" technique=shadowmap
lighting=()
while [ $# -gt 0 ]; do
    case "$1" in
    -h | --help) usage; exit 0 ;;
    --rounds | --size | --driver | --duration | --frames | --build | --technique | --lighting)
        [ $# -ge 2 ] || die 2 "$1: expected a value (see --help)"
        case "$1" in
        --rounds) rounds=$2 ;;
        --size) size=$2 ;;
        --driver) driver=$2 ;;
        --duration) duration=$2 ;;
        --frames) frames=$2 ;;
        --build) build=$2 ;;
        --technique) technique=$2 ;;
        --lighting) lighting=(--lighting "$2") ;;
        esac
        shift 2 ;;
    *) die 2 "unknown option '$1' (see --help)" ;;
    esac
done
positive() { [[ "$2" =~ ^[1-9][0-9]*$ ]] || die 2 "$1: expected a positive integer, got '$2'"; }
positive --rounds "$rounds"
positive --size "$size"
positive --duration "$duration"
positive --frames "$frames"
[ "$size" -le 4096 ] || die 2 "--size: at most 4096 (the map is twice that per side), got $size"
case "$technique" in *resolution=*) die 2 "--technique: leave resolution out, it is 2 x --size ($((2 * size)))" ;; esac

# What is needed, each missing piece named with what installs it.
horse=/usr/share/glmark2/models/horse.3ds
for tool in glmark2 xvfb-run python3; do
    command -v "$tool" >/dev/null ||
        die 3 "$tool is not installed: bash scripts/install-deps.sh perf"
done
[ -f "$horse" ] || die 3 "$horse is missing (glmark2-data): bash scripts/install-deps.sh perf"
[ -x "$build/bench" ] || die 3 "$build/bench is missing: cmake --build $build --target bench (or --build DIR)"
scene="$root/results/perf/horse.json"
[ -f "$scene" ] || die 1 "$scene is missing from the checkout"

# glmark2 on the chosen driver: bench prints the driver's variables (DriverTable's, the ones --driver
# sets for itself); under Xvfb the GLX path needs LD_LIBRARY_PATH (libGLX_mesa) and LIBGL_DRIVERS_PATH
# (swrast_dri.so) of the prefix.
glmark_env=()
if [ "$driver" != system ]; then
    prefix=$driver
    if [[ "$driver" != */* ]]; then
        prefix="${SHADOWBENCH_DRIVERS_DIR:-/opt/shadowbench/drivers}/$driver"
        [ -d "$prefix" ] || die 3 "--driver $driver: not installed (no $prefix): bash scripts/install-deps.sh driver"
    fi
    [ -d "$prefix" ] || die 2 "--driver $driver: no such folder"
    lib=""
    for l in usr/lib/x86_64-linux-gnu lib/x86_64-linux-gnu lib64 lib; do
        [ -f "$prefix/$l/libGLX_mesa.so.0" ] && { lib="$prefix/$l"; break; }
    done
    [ -n "$lib" ] || die 3 "--driver $driver: no libGLX_mesa.so.0 in $prefix (glmark2 reaches Mesa through GLX)"
    glmark_env=("LD_LIBRARY_PATH=$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "LIBGL_DRIVERS_PATH=$lib/dri")
fi

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One glmark2 run: prints "<frame time ms> <Mesa version>".
run_glmark2() {
    local log=$tmp/glmark2.log
    if ! env "${glmark_env[@]}" xvfb-run -a -s "-screen 0 ${size}x${size}x24" glmark2 --off-screen \
        -s "${size}x${size}" -b "shadow:duration=$duration" >"$log" 2>&1; then
        tail -n 5 "$log" >&2
        die 1 "glmark2 failed (log above)"
    fi
    local ms version
    ms=$(sed -n 's/.*FrameTime: \([0-9.]*\) ms.*/\1/p' "$log" | tail -n 1)
    # "4.5 (Compatibility Profile) Mesa 25.0.7-2~bpo12+1": the release, as bench's row below gives it.
    version=$(sed -n 's/.*GL_VERSION: .*Mesa \([0-9.]*\).*/Mesa_\1/p' "$log" | head -n 1)
    [ -n "$ms" ] || { tail -n 5 "$log" >&2; die 1 "glmark2 printed no FrameTime (log above)"; }
    echo "$ms ${version:-unknown}"
}

# One bench run: prints "<wall mean ms> <wall median ms> <Mesa version>".
run_bench() {
    local csv=$tmp/bench.csv
    if ! "$build/bench" --driver "$driver" -t "$technique:resolution=$((2 * size))" --scene "$scene" "${lighting[@]}" \
        --camera glmark2 --size "${size}x${size}" --frames "$frames" --warmup 5 --no-timer-check \
        --format csv -q >"$csv" 2>"$tmp/bench.err"; then
        tail -n 5 "$tmp/bench.err" >&2
        die 1 "bench failed (its errors above)"
    fi
    python3 - "$csv" <<'EOF'
import csv, sys
row = list(csv.DictReader(open(sys.argv[1])))[-1]
version = row.get("driver_version", "") or "unknown"
print(row["wall_ms_mean"], row["wall_ms_median"], version.split("-")[0].replace(" ", "_"))
EOF
}

median() { printf "%s\n" "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "load before: $(uptime)"
echo "frame: results/perf/horse.json, camera glmark2, ${size}x${size}, map $((2 * size))^2, driver $driver"
echo "round  glmark2 ms   bench mean ms  bench median ms  bench/glmark2 (mean)"
g_ms=() b_ms=() ratios=()
for ((r = 0; r < rounds; ++r)); do
    if ((r % 2 == 0)); then g=$(run_glmark2); b=$(run_bench); else b=$(run_bench); g=$(run_glmark2); fi
    read -r gms gver <<<"$g"
    read -r bmean bmed bver <<<"$b"
    # Both must have run on the same Mesa: a GLX process that missed the prefix runs the system's.
    [ "$gver" = "$bver" ] ||
        die 1 "round $r: glmark2 ran on ${gver//_/ }, bench on ${bver//_/ }: not the same driver"
    ratio=$(echo "$bmean / $gms" | bc -l)
    g_ms+=("$gms") b_ms+=("$bmean") ratios+=("$ratio")
    printf "%5d  %10.3f   %12.3f   %14.3f   %.3f\n" "$r" "$gms" "$bmean" "$bmed" "$ratio"
done
echo "driver version (both): ${gver//_/ }"
printf "glmark2 frame time median %.3f ms, bench wall mean median %.3f ms\n" "$(median "${g_ms[@]}")" \
    "$(median "${b_ms[@]}")"
printf "ratio bench/glmark2 per round: median %.3f  min %.3f  max %.3f  (%d rounds)\n" "$(median "${ratios[@]}")" \
    "$(printf "%s\n" "${ratios[@]}" | sort -g | head -n 1)" "$(printf "%s\n" "${ratios[@]}" | sort -g | tail -n 1)" \
    "$rounds"
echo "load after: $(uptime)"
