#!/usr/bin/env bash
# The proof of `bench bisect` (results/bisect/README.md): a synthetic history of COMMITS harmless
# commits on top of this checkout's HEAD, in a clone of its own, each adding a comment line to a source
# file compiled into bench (so every probe really rebuilds something), with one real regression among
# them: shadow maps stop culling casters (techniques/shadowmap/ShadowMapGL.cpp draws every object into
# the map, as SHADOWBENCH_INJECT=no_caster_culling does), so layer A's work of shadowmap_aircraft grows.
# Then `bench bisect` on it must name the injected commit, in at most ceil(log2 N) + 1 builds (N the
# commits after GOOD, the injected one included), and the script prints how long it took.
# Not part of CI: the first build of the bisection's build folder is a full build of bench.
# Usage: bash scripts/bisect-proof.sh [COMMITS (default 64)] [AT: the injected commit's place, 1..N (default 41)]
# SHADOWBENCH_BENCH names another bench binary; SHADOWBENCH_PROOF_DIR the folder of the clone and the
# build folder (default ${TMPDIR:-/var/tmp}/shadowbench-bisect-proof, kept so that a rerun reuses ccache).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
harmless="${1:-64}"
at="${2:-41}"
bench="${SHADOWBENCH_BENCH:-$root/build/bench}"
work="${SHADOWBENCH_PROOF_DIR:-${TMPDIR:-/var/tmp}/shadowbench-bisect-proof}"
n=$((harmless + 1))
if [ "$at" -lt 1 ] || [ "$at" -gt "$n" ]; then echo "AT must be in 1..$n" >&2; exit 2; fi
[ -x "$bench" ] || { echo "no bench binary at $bench (build it first)" >&2; exit 2; }

repo="$work/repo"
rm -rf "$repo"
mkdir -p "$work"
head="$(git -C "$root" rev-parse HEAD)"
git clone -q --no-checkout "$root" "$repo"
git -C "$repo" checkout -q --detach "$head"
git() { command git -C "$repo" -c user.name="bisect proof" -c user.email=proof@localhost "$@"; }

# Files compiled into bench that no probe's configuration depends on: a comment changes no work.
files=(techniques/none/NoneGL.cpp bench/lib/gate/WorkGate.cpp core/Suggestion.cpp scenes/SceneLoader.cpp)
for f in "${files[@]}"; do [ -f "$repo/$f" ] || { echo "no $f in the checkout" >&2; exit 1; }; done
regression_line='mDrawAllIntoMap = injected(Injection::NoCasterCulling);'
injected=""
for i in $(seq 1 "$n"); do
  if [ "$i" -eq "$at" ]; then
    f=techniques/shadowmap/ShadowMapGL.cpp
    grep -qF "$regression_line" "$repo/$f" || { echo "the regression's line is not in $f any more" >&2; exit 1; }
    sed -i "s/$regression_line/mDrawAllIntoMap = true; \/\/ every object into the map, receivers included/" "$repo/$f"
    git commit -q -am "proof: shadow maps draw every object into the map (the injected regression)"
    injected="$(git rev-parse HEAD)"
  else
    f="${files[$((i % ${#files[@]}))]}"
    echo "// A harmless line of the bisection proof, number $i." >> "$repo/$f"
    git commit -q -am "proof: harmless comment $i in $f"
  fi
done
echo "history: $n commits on top of ${head:0:12}, the injected regression is commit $at (${injected:0:12})"

start=$(date +%s)
set +e
"$bench" bisect "$head" "$(git rev-parse HEAD)" -c shadowmap_aircraft --repo "$repo" \
  --suite "$repo/results/ci/suite.json" --build-dir "$work/cache" --json "$work/bisect.json"
code=$?
set -e
seconds=$(( $(date +%s) - start ))
echo "bench bisect exit code $code after ${seconds} s"
/usr/bin/python3 - "$work/bisect.json" "$injected" "$n" "$seconds" <<'PY'
import json, math, sys
path, injected, n, seconds = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
r = json.load(open(path))
found = r.get("first_changed", {}).get("commit", "")
limit = math.ceil(math.log2(n)) + 1
builds = r["builds"]
print(f"found {found[:12] or 'nothing'} (injected {injected[:12]}); builds {builds} of at most "
      f"ceil(log2 {n}) + 1 = {limit}; {len(r['steps'])} steps; total {seconds} s")
for s in r["steps"]:
    print(f"  {s['commit'][:12]} {s['verdict']:9} build {s['build_s']:6.1f} s  run {s['run_s']:5.1f} s  {s['subject'][:60]}")
ok = found == injected and builds <= limit
print("PROOF", "PASSED" if ok else "FAILED")
sys.exit(0 if ok else 1)
PY
