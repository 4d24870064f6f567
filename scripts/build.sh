#!/usr/bin/env bash
# Installs what is missing (scripts/install-deps.sh), configures and builds shadowbench (Release) in
# build/ through the "release" preset of CMakePresets.json, so `cmake --preset release` by hand and this
# script configure the same folder the same way (Ninja, Release). Extra arguments go to cmake's
# configure step.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
(cd "$root" && cmake --preset release "$@" >/dev/null)
cmake --build "$root/build" --parallel "$(nproc)"
