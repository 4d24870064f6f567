#!/usr/bin/env bash
# The measurements behind results/raytraced/README.md: ray-traced shadows (techniques/raytraced/) against
# the shadow-map family and shadow volumes on Vulkan, all on the driver that offers ray queries (lavapipe
# of Mesa 25.0.7), and what its acceleration structures cost as the scene grows. Every timed comparison
# runs its techniques in one process in interleaved rounds (bench --repeat K: A B C, A B C ...) and is
# reported as ratios within a round: a shared machine's wall time moves by tens of percent from run to
# run, a ratio measured side by side far less. Accuracy, counters and exact work do not depend on load.
# Sections (each writes its CSVs and the consoles beside them into the output folder):
#   accuracy  hard lights, the scenes of results/family/README.md (aircraft, city, teapot: directional;
#             point_light, jack_o_lantern: point): every technique judged against the Embree reference
#             in one `bench accuracy` run per scene, --repeat K           accuracy_<scene>.csv/.txt
#   soft      area lights (results/family/scenes, results/proxy/scenes): visibility RMSE against the
#             area-light reference, the same way                          soft_<scene>.csv/.txt
#   build     the structures' build times (counters bottom_levels_build_ms, top_level_build_ms) and
#             structure_bytes: one aircraft at growing tessellation (bottom levels), growing instance
#             counts (top level); one process per configuration, 2K rounds round-robin   build.csv
#   rays      frame time against rays x log2(triangles): none and raytraced side by side over sizes x
#             scene sizes; the fit is the summary's                       rays.csv, rays_<config>.txt
#   order     the top level's traversal against the order of its instances: a grid of N spheres whose
#             instances are listed row by row (neighbours next to each other) or shuffled, the same
#             geometry and rays; two processes per N in alternating order, none and raytraced side by
#             side in each (scenes generated into scenes/)                order.csv, order_<n>_<kind>.txt
#   motion    aircraft_day in motion (the top level rebuilt every frame, the `structures` pass) at
#             growing instance counts, none and raytraced side by side    motion.csv, motion_<n>.txt
# Then tables.md (the README's tables) and figures (*.png) from /usr/bin/python3 tools/raytraced_summary.py.
# machine.txt records the machine, the driver and the load (uptime) before and after every section (a run
# of some sections appends its block to the earlier run's).
set -euo pipefail

usage() {
    cat <<'EOF'
Usage: bash scripts/raytraced-study.sh [options]

Measures raytraced (every mode the build offers) against shadowmap, cascaded, pcss, vsm, volume
(cubemap and paraboloid under point lights) on Vulkan, and the cost of its acceleration structures,
all on one driver; writes CSVs, consoles, tables.md and figures into the output folder.

Options:
  --out DIR          output folder [${TMPDIR:-/tmp}/shadowbench-raytraced-study]; the committed results
                     are regenerated only when asked for: --out results/raytraced
  --sections LIST    comma-separated, any of accuracy,soft,build,rays,order,motion [all]
  --rounds K         interleaved rounds of every timed comparison [3]
  --size WxH         the accuracy section's frame size [512x512]
  --driver NAME      the driver with ray queries, as bench --driver takes it [mesa-25.0.7]
  --build DIR        the build folder holding bench [build]
  --quick            smallest sizes and one round: checks the script end to end in a few minutes;
                     its numbers mean nothing
  --no-summary       the CSVs and consoles only: no tables.md or figures (no python3 needed); run
                     /usr/bin/python3 tools/raytraced_summary.py DIR on the folder later
  -h, --help         this text

Exit codes: 0 done, 2 wrong input, 3 bench, the driver or python3's modules missing, 1 a run failed.

Examples:
  bash scripts/raytraced-study.sh --out results/raytraced          # the committed results (~15 min, 2 cores)
  bash scripts/raytraced-study.sh --sections build,motion          # structure costs only, to /tmp
  bash scripts/raytraced-study.sh --quick --out /tmp/rt-check      # end to end, tiny
EOF
}

die() { # die CODE MESSAGE
    echo "raytraced-study: ${*:2}" >&2
    exit "$1"
}

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
all_sections="accuracy,soft,build,rays,order,motion"
out="${TMPDIR:-/tmp}/shadowbench-raytraced-study" sections_arg=$all_sections
rounds=3 size=512x512 driver=mesa-25.0.7 build="$root/build" quick=0 summary=1
while [ $# -gt 0 ]; do
    case "$1" in
    -h | --help) usage; exit 0 ;;
    --quick) quick=1; shift ;;
    --no-summary) summary=0; shift ;;
    --out | --sections | --rounds | --size | --driver | --build)
        [ $# -ge 2 ] || die 2 "$1: expected a value (see --help)"
        case "$1" in
        --out) out=$2 ;;
        --sections) sections_arg=$2 ;;
        --rounds) rounds=$2 ;;
        --size) size=$2 ;;
        --driver) driver=$2 ;;
        --build) build=$2 ;;
        esac
        shift 2 ;;
    *) die 2 "unknown option '$1' (see --help)" ;;
    esac
done
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || die 2 "--rounds: expected a positive integer, got '$rounds'"
[[ "$size" =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || die 2 "--size: expected WxH (512x512), got '$size'"
[ -n "$out" ] || die 2 "--out: expected a folder"
IFS=, read -r -a sections <<<"$sections_arg"
[ ${#sections[@]} -gt 0 ] || die 2 "--sections: expected a list of $all_sections"
for s in "${sections[@]}"; do
    case "$s" in accuracy | soft | build | rays | order | motion) ;;
    *) die 2 "--sections: unknown section '$s' (known: $all_sections)" ;;
    esac
done
wanted() { [[ " ${sections[*]} " == *" $1 "* ]]; }

# What is needed, each missing piece named with what provides it.
bench="$build/bench"
[ -x "$bench" ] || die 3 "$bench is missing: cmake --build $build --target bench (or --build DIR)"
[ "$summary" -eq 0 ] || /usr/bin/python3 -c 'import matplotlib, numpy, pandas' 2>/dev/null ||
    die 3 "/usr/bin/python3 lacks matplotlib, numpy or pandas: apt-get install python3-matplotlib" \
        "python3-pandas"
msg="$("$bench" --driver "$driver" --api vulkan -t raytraced --scene sphere_plane --size 16x16 --frames 1 \
    --warmup 0 --no-timer-check -q 2>&1 >/dev/null)" && code=0 || code=$?
[ "$code" -eq 0 ] || die "$code" "raytraced on --driver $driver: ${msg##*$'\n'}"

# The modes of raytraced this build offers (bench --list: "mode  enum  default hard  {hard, soft}") and
# the range of `rays` ("[1, 256]"): the soft and guided modes are measured only where they exist.
listing="$("$bench" --list | awk '/^raytraced /{on=1; next} on && /^[^ ]/{on=0} on')"
modes="$(sed -n 's/^ *mode .*{\([^}]*\)}.*/\1/p' <<<"$listing" | tr -d ' ' | tr , ' ')"
rays_range="$(sed -n 's/^ *rays .*\[\([0-9]*\), *\([0-9]*\)\].*/\1 \2/p' <<<"$listing")"
has_mode() { [[ " $modes " == *" $1 "* ]]; }
rt=(-t raytraced:mode=hard)
skipped=()
if has_mode soft && [ -n "$rays_range" ]; then
    read -r lo hi <<<"$rays_range"
    for r in 1 4 16 64; do
        if [ "$r" -ge "$lo" ] && [ "$r" -le "$hi" ]; then rt+=(-t "raytraced:mode=soft:rays=$r")
        else skipped+=("raytraced:mode=soft:rays=$r (rays range [$lo, $hi])"); fi
    done
elif has_mode soft; then
    skipped+=("raytraced:mode=soft (no property rays in bench --list)")
else
    skipped+=("raytraced:mode=soft (not in this build: modes {${modes// /, }})")
fi
if has_mode guided; then rt+=(-t raytraced:mode=guided)
else skipped+=("raytraced:mode=guided (not in this build: modes {${modes// /, }})"); fi
for s in "${skipped[@]}"; do echo "raytraced-study: skipped $s" >&2; done

# Sizes: --quick shrinks every one (and the rounds to 1) so that the whole script runs in minutes.
small=256x256 soft_size=384x384 frames=3 warmup=1
rays_sizes=(256x256 512x512) motion_counts=(40 200 1000) build_instances=(1 10 100 1000 3000)
build_tess=(0.5 1 2 4 8 16) order_sides=(8 16 32 64)
if [ "$quick" -eq 1 ]; then
    rounds=1 size=64x64 small=64x64 soft_size=64x64 frames=1 warmup=0
    rays_sizes=(32x32 64x64) motion_counts=(4 40) build_instances=(1 10) build_tess=(0.5 1) order_sides=(4)
fi

mkdir -p "$out"
out="$(cd "$out" && pwd)"
echo "raytraced-study: writing into $out" >&2
machine="$out/machine.txt"
# A run of every section starts machine.txt afresh; a run of some appends its own block, so that the load
# of the sections it leaves as they were stays recorded beside their CSVs.
every=1
for s in ${all_sections//,/ }; do wanted "$s" || every=0; done
if [ "$every" -eq 1 ] || [ ! -s "$machine" ]; then : >"$machine"; else echo >>"$machine"; fi
{
    echo "sections: $sections_arg"
    echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    echo "commit: $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
    echo "cpu: $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1) x $(nproc)"
    echo "os: $(sed -n 's/^PRETTY_NAME="\(.*\)"$/\1/p' /etc/os-release)"
    echo "driver: $driver; raytraced modes: {${modes// /, }}"
    for s in "${skipped[@]}"; do echo "skipped: $s"; done
    echo "options: rounds $rounds, accuracy size $size, quick $quick"
} >>"$machine"
load() { echo "$1: $(uptime | sed 's/.*load average/load average/')" >>"$machine"; }

step=0
run() { # run LOG ARGS...: one bench run, its console into LOG, progress on stderr
    local log=$1
    shift
    step=$((step + 1))
    echo "[$step $(date +%H:%M:%S)] bench --driver $driver $*" >&2
    local code=0
    "$bench" --driver "$driver" "$@" >"$log" 2>&1 || code=$?
    if [ "$code" -ne 0 ]; then
        tail -n 3 "$log" >&2
        die 1 "bench failed (exit $code): $log"
    fi
}
vk=(--api vulkan --no-timer-check)

if wanted accuracy; then
    load "accuracy begins"
    rm -f "$out"/accuracy_*.csv "$out"/accuracy_*.txt
    # The family's hard-light scenes, each scene's default camera (far). Under point lights the flat
    # maps refuse (exit 3: they need an omni map), so those scenes take the omni members instead; the
    # first technique of each run is the baseline of its ratios.
    for scene in aircraft city teapot point_light jack_o_lantern; do
        case "$scene" in
        point_light | jack_o_lantern) maps=(-t cubemap -t paraboloid -t volume) ;;
        *) maps=(-t shadowmap -t cascaded -t pcss -t vsm -t volume) ;;
        esac
        run "$out/accuracy_$scene.txt" accuracy "${vk[@]}" "${maps[@]}" "${rt[@]}" --scene "$scene" \
            --size "$size" --frames "$frames" --warmup "$warmup" --repeat "$rounds" --no-stability \
            --csv "$out/accuracy_$scene.csv"
    done
    load "accuracy ends"
fi

if wanted soft; then
    load "soft begins"
    rm -f "$out"/soft_*.csv "$out"/soft_*.txt
    # A small and a large spot emitter and a 10-degree sun, camera mid (results/family/README.md, "Soft
    # shadows"): the hard answers against pcss, the family's best, and every ray-traced mode.
    for file in results/family/scenes/soft_disk_small.json results/family/scenes/soft_rect_large.json \
        results/proxy/scenes/soft_sun_10.json; do
        name="$(basename "$file" .json)"
        name="${name#soft_}"
        run "$out/soft_$name.txt" accuracy "${vk[@]}" -t shadowmap -t pcss -t vsm "${rt[@]}" \
            --scene "$root/$file" --camera mid --size "$soft_size" --frames "$frames" --warmup "$warmup" \
            --repeat "$rounds" --no-stability --ref-samples 64 --csv "$out/soft_$name.csv"
    done
    load "soft ends"
fi

if wanted build; then
    load "build begins"
    rm -f "$out/build.csv" "$out/build.txt"
    # One process per configuration (a run holds one scene), the configurations in turn K times; the
    # builds happen before the first frame, so one small frame is enough. Bottom levels: one aircraft
    # (and the ground) at growing tessellation; top level: aircraft at its coarsest, growing in number.
    configs=()
    for t in "${build_tess[@]}"; do configs+=("1 $t"); done
    for n in "${build_instances[@]}"; do [ "$n" -eq 1 ] || configs+=("$n 0.5"); done
    # Twice the rounds: a build of a few milliseconds is at the mercy of the scheduler on a loaded machine
    # (a delay only adds, so the summary fits the minimum over the rounds).
    for ((k = 1; k <= 2 * rounds; k++)); do
        for c in "${configs[@]}"; do
            read -r n t <<<"$c"
            run "$out/build.txt" "${vk[@]}" -t raytraced:mode=hard --scene aircraft --instances "$n" \
                --tess-factor "$t" --size 32x32 --frames 1 --warmup 0 -q --csv "$out/build.csv"
        done
    done
    load "build ends"
fi

if wanted rays; then
    load "rays begins"
    rm -f "$out/rays.csv" "$out"/rays_*.txt
    # Scene sizes from 1.2 thousand to 2.6 million triangles (instances x tessellation factor of the
    # aircraft), each at three frame sizes (the rays): none and raytraced in one run, K rounds.
    for c in "1 0.5" "1 4" "1 16" "20 1" "200 1" "1000 0.5"; do
        read -r n t <<<"$c"
        [ "$quick" -eq 0 ] || [ "$n" -le 20 ] || continue
        for s in "${rays_sizes[@]}"; do
            run "$out/rays_${n}x${t}_$s.txt" "${vk[@]}" -t none -t raytraced:mode=hard --scene aircraft \
                --instances "$n" --tess-factor "$t" --size "$s" --frames "$frames" --warmup "$warmup" \
                --repeat "$rounds" --csv "$out/rays.csv"
        done
    done
    load "rays ends"
fi

if wanted order; then
    load "order begins"
    rm -f "$out/order.csv" "$out"/order_*.txt
    rm -rf "$out/scenes"
    mkdir -p "$out/scenes"
    # side x side spheres (radius 0.6, 2.5 apart) standing over a ground, a directional light, a camera
    # straight above that sees the whole grid: every pixel is a surface that traces one ray. sorted lists
    # the spheres row by row, shuffled in a fixed random order (seed 7); nothing else differs.
    /usr/bin/python3 - "$out/scenes" "${order_sides[@]}" <<'PY'
import json, random, sys
folder, sides = sys.argv[1], [int(s) for s in sys.argv[2:]]
for side in sides:
    half = (side - 1) * 2.5 / 2
    grid = [{"mesh": "ball", "position": [round(-half + j * 2.5, 3), 1.0, round(-half + i * 2.5, 3)],
             "color": [0.8, 0.3, 0.2]} for i in range(side) for j in range(side)]
    shuffled = grid[:]
    random.Random(7).shuffle(shuffled)
    for kind, balls in (("sorted", grid), ("shuffled", shuffled)):
        scene = {"name": f"order_{side}_{kind}",
                 "description": f"{side}x{side} spheres over a ground, instances {kind} "
                                "(scripts/raytraced-study.sh, section order)",
                 "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.6, "tessellation": 8},
                            {"name": "ground", "generator": "plane", "size": 2 * half + 10,
                             "tessellation": 8}],
                 "instances": [{"mesh": "ground", "position": [0, 0, 0], "casts_shadow": False,
                                "color": [0.6, 0.6, 0.6]}] + balls,
                 "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3]}],
                 "cameras": [{"name": "top", "eye": [0, 1.8 * half + 4, 0.01], "target": [0, 0, 0],
                              "up": [0, 0, -1], "fov": 60, "near": 1, "far": 4 * half + 20}],
                 "effects": ["hard_shadows"]}
        with open(f"{folder}/order_{side}_{kind}.json", "w") as f:
            json.dump(scene, f, indent=1)
PY
    k=0
    for side in "${order_sides[@]}"; do
        k=$((k + 1))
        kinds=(sorted shuffled shuffled sorted)
        [ $((k % 2)) -eq 1 ] || kinds=(shuffled sorted sorted shuffled)
        [ "$quick" -eq 0 ] || kinds=(sorted shuffled)
        for kind in "${kinds[@]}"; do
            run "$out/order_${side}_$kind.txt" "${vk[@]}" -t none -t raytraced:mode=hard \
                --scene "$out/scenes/order_${side}_$kind.json" --camera top --size "$small" \
                --frames "$frames" --warmup "$warmup" --repeat "$rounds" --csv "$out/order.csv"
        done
    done
    load "order ends"
fi

if wanted motion; then
    load "motion begins"
    rm -f "$out/motion.csv" "$out"/motion_*.txt
    # aircraft_day moves its sun and its aircraft every frame (camera far: the camera stays), so the top
    # level is rebuilt inside every frame; none beside it moves the same scene and draws the same
    # triangles.
    for n in "${motion_counts[@]}"; do
        run "$out/motion_$n.txt" "${vk[@]}" -t none -t raytraced:mode=hard --scene aircraft_day \
            --instances "$n" --size "$small" --frames "$((frames + 2))" --warmup "$warmup" \
            --repeat "$rounds" --csv "$out/motion.csv"
    done
    load "motion ends"
fi

if [ "$summary" -eq 0 ]; then
    echo "raytraced-study: done: $out (no summary: /usr/bin/python3 tools/raytraced_summary.py $out)" >&2
    exit 0
fi
echo "raytraced-study: tables and figures" >&2
/usr/bin/python3 "$root/tools/raytraced_summary.py" "$out" >"$out/tables.md" ||
    die 1 "tools/raytraced_summary.py failed on $out"
echo "raytraced-study: done: $out/tables.md" >&2
