#!/usr/bin/env bash
# The measurements behind results/family/README.md's sections on the newer members (evsm, msm, virtual,
# cascaded:fit=sdsm, screen-space contact shadows). Not run in CI. Every timed comparison runs its
# configurations in one process in interleaved rounds (bench --repeat K: A B C, A B C ...) and is reported
# as ratios within a round; accuracy,
# counters, pages and memory estimates are exact and do not depend on load.
# Sections (each writes <section>_*.csv and the consoles <section>_*.txt into the output folder):
#   accuracy  every map member against the Embree reference (512x512, the scenes' own cameras, 5 frames
#             after 2, no stability pass), one `bench accuracy` run per scene: wrong pixels and the
#             texels per pixel (acc_texels_per_pixel_*)                   accuracy_<scene>.csv/.txt
#   lod       virtual at lod_bias -1 and -2 on the same scenes           accuracy_lod_<scene>.csv/.txt
#   cost      the same members side by side on aircraft x50, --repeat K     cost_members.csv/.txt
#   virtual   virtual (cache on and off) against cascaded at 4096^2 x 4 and its default: pages and the
#             memory estimates, static (aircraft) and in motion (aircraft_day: the sun and the flight;
#             results/family/scenes/aircraft_flight.json: the flight alone), accuracy and time side by
#             side; then virtual at lod_bias -2 (the cascades' texels per pixel) against the 4096^2
#             cascades, static and in flight, and its path accuracy       virtual_*.csv/.txt, memory.txt
#   contact   contact=true:contact_length=1:contact_steps=16 on and off, at the hard-case table's large
#             bias (512^2, 2000 / 32) and at each member's default bias, contact_point_sun (low) and
#             contact_point_lamp (low), and its time side by side (aircraft x50, point_light)
#                                                                          contact_*.csv/.txt
#   moments   light leak on the constructed overlaps (moments_bleeding, moments_bleeding_slab, camera
#             crossing), evsm's positive exponent swept on the slab, and the time against vsm side by
#             side on aircraft                                             moments_*.csv/.txt
# memory.txt: each configuration's resource estimate (techniques/ResourceEstimate.h), read from the
# --max-memory-gib refusal, which names it (exit 2 on purpose; one aircraft at 16x16 keeps the scene and
# the frame targets under the 1 MiB limit, so only the technique's maps exceed it).
set -euo pipefail

usage() {
    cat <<'EOF'
Usage: bash scripts/family-study.sh [options] [section ...]

Sections: accuracy lod cost virtual contact moments (default: all).

Options:
  --out DIR     output folder [${TMPDIR:-/tmp}/shadowbench-family-study]; the committed results are
                regenerated only when asked for: --out results/family
  --bench PATH  the bench binary [build/bench]
  --repeat K    rounds of the timed comparisons [3]
  -h, --help    this text
EOF
}

out="${TMPDIR:-/tmp}/shadowbench-family-study"
bench=build/bench
repeat=3
sections=()
while [[ $# -gt 0 ]]; do
    case "$1" in
    --out) out="$2"; shift 2 ;;
    --bench) bench="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    -h | --help) usage; exit 0 ;;
    -*) echo "family-study.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    *) sections+=("$1"); shift ;;
    esac
done
[[ ${#sections[@]} -gt 0 ]] || sections=(accuracy lod cost virtual contact moments)
[[ -x "$bench" ]] || { echo "family-study.sh: no bench binary at '$bench' (build first)" >&2; exit 3; }
mkdir -p "$out"

hard=tests/hard/scenes
timed=(--no-timer-check --repeat "$repeat")

# Runs bench with the console into <name>.txt and the rows into <name>.csv (an earlier CSV replaced).
run() {
    local name="$1"
    shift
    rm -f "$out/$name.csv"
    echo "== $name: $bench $*" | tee "$out/$name.txt"
    "$bench" "$@" --csv "$out/$name.csv" 2>&1 | tee -a "$out/$name.txt"
}

machine() {
    { echo "== $1 $(date -u +%FT%TZ)"; uptime; } >>"$out/machine.txt"
}

members=(-t shadowmap -t cubemap -t paraboloid -t cascaded -t cascaded:fit=sdsm -t pcss -t vsm -t esm
    -t evsm -t evsm:components=2 -t msm -t msm:format=float -t virtual)

section_accuracy() {
    local s
    for s in aircraft city; do
        run "accuracy_$s" accuracy "${members[@]}" --scene "$s" --size 512x512 --frames 5 --warmup 2 \
            --no-stability
    done
}

# virtual's level choice sharpened (lod_bias -1, -2: texels 2x, 4x smaller a side than a pixel's
# footprint), to set against the flat maps' texels per pixel.
section_lod() {
    local s
    for s in aircraft city; do
        run "accuracy_lod_$s" accuracy -t virtual:lod_bias=-1 -t virtual:lod_bias=-2 --scene "$s" \
            --size 512x512 --frames 5 --warmup 2 --no-stability
    done
}

section_cost() {
    run cost_members "${members[@]}" --scene aircraft --instances 50 --size 512x512 --frames 10 --warmup 3 \
        "${timed[@]}"
}

# What each configuration declares it holds (the --max-memory-gib refusal names the estimate).
memory() {
    for t in "$@"; do
        "$bench" -t "$t" --scene aircraft --instances 1 --size 16x16 --frames 1 --max-memory-gib 0.001 2>&1 |
            sed -n 's/.*-t \([^ ]*\): estimated memory .*(technique \(.*\)), scene .*/\1: \2)/p' || true
    done
}

section_virtual() {
    local vc=(-t virtual -t virtual:cache=false -t cascaded:resolution=4096 -t cascaded)
    memory virtual virtual:cache=false cascaded:resolution=4096 cascaded shadowmap vsm esm evsm \
        evsm:components=2 msm msm:format=float >"$out/memory.txt"
    cat "$out/memory.txt"
    run virtual_static "${vc[@]}" --scene aircraft --size 512x512 --frames 10 --warmup 3 "${timed[@]}"
    run virtual_motion "${vc[@]}" --scene aircraft_day --size 512x512 --frames 10 --warmup 3 \
        --path-frames 60 "${timed[@]}"
    run virtual_flight "${vc[@]}" --scene results/family/scenes/aircraft_flight.json --size 512x512 \
        --frames 10 --warmup 3 --path-frames 60 "${timed[@]}"
    run virtual_accuracy accuracy -t virtual -t cascaded:resolution=4096 -t cascaded --scene aircraft_day \
        --size 512x512 --frames 5 --warmup 2 --path-frames 60 --no-stability
    # virtual at lod_bias -2, the texels per pixel of 4096^2 cascades (section lod), against them.
    local vs=(-t virtual:lod_bias=-2 -t virtual:lod_bias=-2:cache=false -t cascaded:resolution=4096)
    run virtual_sharp_static "${vs[@]}" --scene aircraft --size 512x512 --frames 10 --warmup 3 "${timed[@]}"
    run virtual_sharp_flight "${vs[@]}" --scene results/family/scenes/aircraft_flight.json --size 512x512 \
        --frames 10 --warmup 3 --path-frames 60 "${timed[@]}"
    run virtual_sharp_accuracy accuracy -t virtual:lod_bias=-2 --scene aircraft_day --size 512x512 --frames 5 \
        --warmup 2 --path-frames 60 --no-stability
}

section_contact() {
    local big=":resolution=512:bias_slope=32:bias_constant=2000"
    local on=":contact=true:contact_length=1:contact_steps=16"
    local sun=() lamp=() t
    for t in shadowmap cascaded pcss; do sun+=(-t "$t$big" -t "$t$big$on" -t "$t" -t "$t:${on#:}"); done
    sun+=(-t virtual:bias_slope=32:bias_constant=2000 -t "virtual:bias_slope=32:bias_constant=2000$on"
        -t virtual -t "virtual:${on#:}")
    for t in cubemap paraboloid; do lamp+=(-t "$t$big" -t "$t$big$on" -t "$t" -t "$t:${on#:}"); done
    run contact_sun accuracy "${sun[@]}" --scene "$hard/contact_point_sun.json" --camera low --size 384x384 \
        --frames 3 --warmup 1 --no-stability
    run contact_lamp accuracy "${lamp[@]}" --scene "$hard/contact_point_lamp.json" --camera low \
        --size 384x384 --frames 3 --warmup 1 --no-stability
    run contact_cost -t shadowmap -t "shadowmap:${on#:}" -t cascaded -t "cascaded:${on#:}" -t virtual \
        -t "virtual:${on#:}" --scene aircraft --instances 50 --size 512x512 --frames 10 --warmup 3 "${timed[@]}"
    run contact_cost_pcss -t pcss -t "pcss:${on#:}" --scene aircraft --instances 50 --size 512x512 --frames 10 \
        --warmup 3 "${timed[@]}"
    run contact_cost_omni -t cubemap -t "cubemap:${on#:}" -t paraboloid -t "paraboloid:${on#:}" \
        --scene point_light --size 512x512 --frames 10 --warmup 3 "${timed[@]}"
}

section_moments() {
    local s
    local m=(-t vsm -t esm -t evsm:components=2 -t evsm -t msm -t msm:format=float)
    for s in moments_bleeding moments_bleeding_slab; do
        run "moments_${s#moments_}" accuracy "${m[@]}" --scene "$hard/$s.json" --camera crossing --size 384x384 \
            --frames 3 --warmup 1 --no-stability
    done
    # Where evsm's positive warp stops separating the slab's depths: c+ from 1 up to its default 40.
    run moments_exponent accuracy -t evsm:components=2:exponent_positive=1 \
        -t evsm:components=2:exponent_positive=2.5 -t evsm:components=2:exponent_positive=5 \
        -t evsm:components=2:exponent_positive=10 -t evsm:components=2:exponent_positive=20 \
        -t evsm:components=2:exponent_positive=40 --scene "$hard/moments_bleeding_slab.json" --camera crossing \
        --size 384x384 --frames 3 --warmup 1 --no-stability
    run moments_cost "${m[@]}" --scene aircraft --instances 50 --size 512x512 --frames 10 --warmup 3 \
        "${timed[@]}"
}

for s in "${sections[@]}"; do
    declare -F "section_$s" >/dev/null || { echo "family-study.sh: unknown section '$s'" >&2; exit 2; }
    machine "$s start"
    "section_$s"
    machine "$s end"
done
