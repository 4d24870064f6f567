#!/usr/bin/env bash
# The measurements behind results/effects/README.md: what each effect a scene can ask for costs, with
# and without it side by side in one run, and what `-t auto` chooses on every built-in scene.
#   bleeding.csv    proxy with colour bleeding compiled in and out (painting_machine asks for it)
#   modulate.csv    proxy with and without the egg-shaped modulation towards the lights
#   fill_light_<round>.csv  a key and a fill light, the fill casting a shadow or not ("casts_shadows": false):
#                   sweeps over the two scene files of results/effects/scenes/
#   auto.csv        -t auto per built-in scene at 256x256 (calibration cached in auto-calibration.csv)
# Wall times are ratios measured side by side (interleaved rounds); the exact work columns (load_*,
# work_*) are what the saving is in, and they do not move with load.
# Usage: bash scripts/effects.sh [output folder, default results/effects] (about 15 minutes on 2 cores)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/results/effects}"
bench="$root/build/bench"
[ -x "$bench" ] || bash "$root/scripts/build.sh"
mkdir -p "$out"
rm -f "$out"/{bleeding,modulate,auto}.csv "$out"/fill_light_*.csv "$out/auto-calibration.csv"
run() { echo "+ bench $*" >&2; "$bench" "$@"; }

run -t proxy:bleeding=on -t proxy:bleeding=off --scene painting_machine --repeat 5 --csv "$out/bleeding.csv"
run -t proxy:modulate=on -t proxy:modulate=off --scene painting_machine --repeat 5 --csv "$out/modulate.csv"
scenes="$root/results/effects/scenes"
# A run holds one scene, so the two scene files cannot interleave frame by frame: three sweeps
# alternate their order (with, without; without, with; with, without) instead.
with="$scenes/two_lights.json" without="$scenes/two_lights_fill_unshadowed.json"
round=0
for order in "$with,$without" "$without,$with" "$with,$without"; do
  round=$((round + 1)) # a sweep's CSV holds one definition: one file per order
  run sweep -t shadowmap -t volume -t projective -t planar -t vsm --scene "$order" --camera mid \
    --csv "$out/fill_light_$round.csv"
done
for scene in $("$bench" --list | sed -n 's/^scenes: //p' | tr -d ','); do
  run -t auto --scene "$scene" --size 256x256 --calibration "$out/auto-calibration.csv" \
    --csv "$out/auto.csv" || echo "effects: -t auto on $scene: exit $?" >&2
done
