#!/usr/bin/env bash
# Quick start 2: install, build, run the whole test suite through ctest (unit, GL on Mesa llvmpipe,
# CLI). Extra arguments go to ctest, e.g. `bash scripts/test.sh -L unit`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
cd "$root/build"
# Without a display, run under Xvfb so the GLFW backend is tested too (the EGL and OSMesa tests need
# no display either way).
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure --parallel "$(nproc)" "$@"
fi
exec ctest --output-on-failure --parallel "$(nproc)" "$@"
