#!/usr/bin/env bash
# Quick start 2: install, build, run the whole test suite through ctest (unit, GL on Mesa llvmpipe,
# CLI). Extra arguments go to ctest, e.g. `bash scripts/test.sh -L unit`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
cd "$root/build"
exec ctest --output-on-failure --parallel "$(nproc)" "$@"
