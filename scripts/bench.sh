#!/usr/bin/env bash
# Quick start 1: install what the bench program needs, build it alone (no tests), run the default
# benchmark
#   bench --technique shadowmap --instances 200   (built-in aircraft scene, 1024x1024)
# Any arguments replace the defaults, e.g. `bash scripts/bench.sh -t none -t shadowmap --csv r.csv`.
# `bench figures` and `bench report` also need python3 with matplotlib and pandas:
# `bash scripts/install-deps.sh plot`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh" --bench
if [ $# -eq 0 ]; then set -- --technique shadowmap --instances 200; fi
exec "$root/build/bench" "$@"
