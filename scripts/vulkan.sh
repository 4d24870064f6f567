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
# Usage: bash scripts/vulkan.sh [output folder, default results/vulkan]   (about 10 minutes on 2 cores)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/results/vulkan}"
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

measure base_retained --submit retained
measure base_instanced --submit instanced
measure fill --scale 10 --submit retained
measure draws --instances 2000 --scale 0.05 --submit retained
rm -f "$out/immediate.csv"
for _ in 1 2 3; do
  run --api gl "${techniques[@]}" "${common[@]}" --submit immediate --csv "$out/immediate.csv"
done
/usr/bin/python3 "$root/tools/vulkan_summary.py" "$out"
