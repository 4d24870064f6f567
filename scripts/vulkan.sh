#!/usr/bin/env bash
# The measurements behind results/vulkan/README.md: the same scenes and techniques on GL (Mesa llvmpipe)
# and on Vulkan (Mesa lavapipe, the same gallivm rasteriser), side by side. A process runs one API, so
# the two alternate run by run over three rounds (GL first, Vulkan first, GL first); every row lands in
# one CSV per configuration with its `api` column, and tools/vulkan_summary.py pairs them.
#   <config>.csv   wall and CPU record/submit times, the census's exact work (work_*, load_*)
# Configurations (512x512, the aircraft scene, camera far, 30 frames after 5 warm-up):
#   base       200 instances: none, shadowmap, volume, retained and instanced submission
#   fill       scale 10: the rasteriser's fragments dominate
#   draws      2000 instances at scale 0.05: per-draw cost (the application thread) dominates
#   immediate  GL's glBegin/glEnd submission of the base scene (GL only: Vulkan has no such mode)
#   every      every technique of the registry (bench --list), 256x256, 100 instances, 20 frames after 3
#              warm-up: where the API changes the answer, technique by technique
#   every_bottleneck  the bottleneck class of one technique per family on either API (bench bottleneck
#              --api, every_bottleneck_<api>_classes.csv)
# Usage: bash scripts/vulkan.sh [output folder, default results/vulkan] [configuration ...]
#   e.g. `bash scripts/vulkan.sh results/vulkan every` (every configuration: about half an hour on 2 cores)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/results/vulkan}"
shift || true
wanted=("$@")
[ ${#wanted[@]} -gt 0 ] || wanted=(base_retained base_instanced fill draws immediate every every_bottleneck)
want() { [[ " ${wanted[*]} " == *" $1 "* ]]; }
bench="$root/build/bench"
[ -x "$bench" ] || bash "$root/scripts/build.sh"
mkdir -p "$out"
run() { echo "+ bench $*" >&2; "$bench" "$@" -q; }
common=(--scene aircraft --camera far --size 512x512 --frames 30 --warmup 5 --no-timer-check)
techniques=(-t none -t shadowmap -t volume)

measure() { # name, then the options of the configuration
  local name="$1"
  shift
  rm -f "$out/$name.csv"
  for order in "gl vulkan" "vulkan gl" "gl vulkan"; do
    for api in $order; do
      run --api "$api" "${techniques[@]}" "${common[@]}" "$@" --csv "$out/$name.csv"
    done
  done
}

want base_retained && measure base_retained --submit retained
want base_instanced && measure base_instanced --submit instanced
want fill && measure fill --scale 10 --submit retained
want draws && measure draws --instances 2000 --scale 0.05 --submit retained
if want immediate; then
  rm -f "$out/immediate.csv"
  for _ in 1 2 3; do
    run --api gl "${techniques[@]}" "${common[@]}" --submit immediate --csv "$out/immediate.csv"
  done
fi
if want every; then
  # Every technique with both forms on the aircraft under its sun (cubemap and paraboloid draw it with
  # their flat maps).
  mapfile -t techniques < <("$bench" --list | awk '/^scenes:/ {exit} /^[a-z]/ {name=$1} /apis: *gl, vulkan/ {print "-t"; print name}')
  common=(--scene aircraft --camera far --size 256x256 --instances 100 --frames 20 --warmup 3 --no-timer-check)
  measure every --submit retained
fi
if want every_bottleneck; then
  # The bottleneck class of one technique per family on either API (every_bottleneck_<api>_classes.csv).
  family=(-t shadowmap -t cubemap -t vsm -t volume -t occluder -t proxy -t planar)
  for api in gl vulkan; do
    rm -f "$out/every_bottleneck_$api.csv" "$out/every_bottleneck_${api}_classes.csv"
    echo "+ bench bottleneck --api $api" >&2
    "$bench" bottleneck --api "$api" "${family[@]}" --scene aircraft --camera far --size 256x256 \
      --instances 100 --frames 10 --warmup 2 --no-timer-check --no-progress \
      --csv "$out/every_bottleneck_$api.csv" >/dev/null
  done
fi
/usr/bin/python3 "$root/tools/vulkan_summary.py" "$out"
