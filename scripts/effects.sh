#!/usr/bin/env bash
# The measurements behind results/effects/README.md: what each effect a scene can ask for costs, with
# and without it side by side in one run, and what `-t auto` chooses on every built-in scene.
#   bleeding.csv    proxy with colour bleeding compiled in and out (painting_machine asks for it)
#   modulate.csv    proxy with and without the egg-shaped modulation towards the lights
#   fill_light_<round>.csv  a key and a fill light, the fill casting a shadow or not ("casts_shadows": false):
#                   sweeps over the two scene files of results/effects/scenes/
#   auto.csv        -t auto per built-in scene at 256x256 (calibration cached in auto-calibration.csv)
#   hybrid_time.csv, hybrid_accuracy.csv  every hybrid of the aircraft against the pure techniques:
#                   wall time in interleaved rounds, accuracy against the Embree reference
#   motion_<round>.csv, motion_accuracy.csv  aircraft_day moving against frozen at noon (--time 0.5),
#                   three runs each in alternating order; accuracy and flicker along the camera path
# Wall times are ratios measured side by side (interleaved rounds); the exact work columns (load_*,
# work_*) are what the saving is in, and they do not move with load.
# Usage: bash scripts/effects.sh [output folder, default results/effects] [section ...]
#   sections: proxy fill auto hybrid motion (default: all; about 30 minutes on 2 cores)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/results/effects}"
shift || true
sections=("$@")
[ ${#sections[@]} -gt 0 ] || sections=(proxy fill auto hybrid motion)
bench="$root/build/bench"
[ -x "$bench" ] || bash "$root/scripts/build.sh"
mkdir -p "$out"
run() { echo "+ bench $*" >&2; "$bench" "$@"; }
wanted() { [[ " ${sections[*]} " == *" $1 "* ]]; }

if wanted proxy; then
rm -f "$out"/{bleeding,modulate}.csv
run -t proxy:bleeding=on -t proxy:bleeding=off --scene painting_machine --repeat 5 --csv "$out/bleeding.csv"
run -t proxy:modulate=on -t proxy:modulate=off --scene painting_machine --repeat 5 --csv "$out/modulate.csv"
fi

if wanted fill; then
rm -f "$out"/fill_light_*.csv
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
fi

if wanted auto; then
rm -f "$out/auto.csv" "$out/auto-calibration.csv"
for scene in $("$bench" --list | sed -n 's/^scenes: //p' | tr -d ','); do
  run -t auto --scene "$scene" --size 256x256 --calibration "$out/auto-calibration.csv" \
    --csv "$out/auto.csv" || echo "effects: -t auto on $scene: exit $?" >&2
done
fi

if wanted hybrid; then
# Coleman's conclusion on the thesis's own scene (200 aircraft, camera far): occluder textures for the
# aircraft's self-shadowing with a shadow map, planar or projective shadows, or blobs on the ground,
# against each pure technique. Times: five interleaved rounds; accuracy: one run against Embree.
rm -f "$out"/hybrid_{time,accuracy}.csv
techniques=(-t none -t occluder -t shadowmap -t volume -t planar -t projective -t blob
            -t hybrid:self=occluder:cast=shadowmap -t hybrid:self=occluder:cast=planar
            -t hybrid:self=occluder:cast=projective -t hybrid:self=occluder:cast=blob
            -t hybrid:self=shadowmap:cast=planar -t hybrid:self=volume:cast=planar)
run "${techniques[@]}" --scene aircraft --size 512x512 --repeat 5 --frames 20 --csv "$out/hybrid_time.csv"
run accuracy "${techniques[@]}" --scene aircraft --size 512x512 --frames 5 --no-stability \
  --csv "$out/hybrid_accuracy.csv"
fi

if wanted motion; then
# The per-frame work a static frame hides: the same techniques on aircraft_day frozen at noon and moving
# (the sun and 40 aircraft), one run each, three rounds in alternating order (a run holds one setting).
rm -f "$out"/motion_*.csv
techniques=(-t none -t shadowmap -t cascaded -t vsm -t volume -t occluder -t proxy -t planar -t projective
            -t blob -t hybrid -t hybrid:self=occluder:cast=planar)
common=(--scene aircraft_day --camera mid --size 512x512 --frames 30)
round=0
for order in "frozen moving" "moving frozen" "frozen moving"; do
  round=$((round + 1))
  for kind in $order; do
    extra=()
    [ "$kind" = frozen ] && extra=(--time 0.5)
    run "${techniques[@]}" "${common[@]}" "${extra[@]}" --csv "$out/motion_$round.csv"
  done
done
run accuracy "${techniques[@]}" --scene aircraft_day --camera path --size 384x384 --frames 5 \
  --csv "$out/motion_accuracy.csv"
fi
