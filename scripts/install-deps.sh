#!/usr/bin/env bash
# The one place that installs the Debian 12 packages shadowbench needs, in groups:
#   bench  the toolchain and the libraries the bench program builds against and runs on (quick start 1,
#          scripts/bench.sh): enough for every measuring subcommand
#   plot   python3 with matplotlib and pandas: `bench figures` (tools/plot.py) and `bench report`
#          (tools/report.py), optional at run time (without them those two stop with an error naming
#          what to install)
#   test   everything: bench, plot, and what the test suite, the sanitizer build and the fuzzers drive
#          (quick start 2, scripts/test.sh); the default
# Idempotent: packages already present are skipped, so it costs ~1 s on a provisioned machine.
# Needs root (apt-get). Usage: bash scripts/install-deps.sh [bench|plot|test]...
set -euo pipefail

BENCH=(
  # toolchain (git: the build stamp's commit; lld, the faster linker, is in the test group: bench alone
  # links once, and CMakeLists.txt falls back to GNU ld without it)
  build-essential cmake ninja-build pkg-config git
  # GL platform: EGL + Mesa llvmpipe, OSMesa fallback, GLFW window, libepoxy loader
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev libglfw3-dev libepoxy-dev
  # Vulkan: the loader and headers, lavapipe (Mesa's CPU device), glslang's library (run-time GLSL to
  # SPIR-V) and the SPIR-V tools it links; glslang-tools because Debian's glslang CMake package refuses
  # to load without its glslangValidator
  libvulkan-dev mesa-vulkan-drivers glslang-dev spirv-tools glslang-tools
  # maths, JSON, CLI, images, model files, ray tracing reference
  libglm-dev nlohmann-json3-dev libcli11-dev libpng-dev libassimp-dev libembree-dev
)
PLOT=(
  # tools/plot.py and tools/report.py run with /usr/bin/python3
  python3 python3-matplotlib python3-pandas
)
TEST=(
  # lld: the linker of every build once present (CMakeLists.txt says why)
  lld
  # the Khronos validation layer the Vulkan tests run under, vulkaninfo
  vulkan-validationlayers vulkan-tools
  # tests (GNU parallel: the sharded-sweep test runs shards the way the README documents)
  googletest libgtest-dev libgmock-dev xvfb xauth parallel
  # the HTML report's test loads the page in a real browser (headless)
  chromium
  # the viewer's test under Xvfb: synthetic key taps (xdotool) and window screenshots (xwd)
  xdotool x11-apps
  # apitrace traces and replays a run (glslang-tools, which compiles every shader permutation, is in
  # the bench group)
  apitrace
  # instructions per measured frame (bench/lib/callgrind/InstructionCount): callgrind and its client-request header
  valgrind
  # real model files the tests load (glmark2's models, assimp's test models)
  glmark2-data assimp-testmodels
  # fuzzing (scripts/fuzz.sh): libFuzzer ships with clang's runtime libraries, not with GCC
  clang libclang-rt-14-dev
  # the workflow templates' test parses them with PyYAML
  python3-yaml
  # the dashboard exports are read back by Google Benchmark's own compare.py (which needs SciPy)
  libbenchmark-tools python3-scipy
  # the package's test: lintian checks the .deb that CPack builds (tests/PackageCliTest.cpp)
  lintian
  # the manual page's tests render it with groff and man (ManPageCliTest, InstallCliTest)
  groff-base man-db
)

[ $# -eq 0 ] && set -- test
PACKAGES=()
for group in "$@"; do
  case "$group" in
    bench) PACKAGES+=("${BENCH[@]}") ;;
    plot) PACKAGES+=("${PLOT[@]}") ;;
    test) PACKAGES+=("${BENCH[@]}" "${PLOT[@]}" "${TEST[@]}") ;;
    *) echo "install-deps: unknown group '$group' (bench, plot or test)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages of '$*' present"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  SUDO=sudo
  command -v sudo >/dev/null || { echo "install-deps: need root to install: ${missing[*]}" >&2; exit 1; }
else
  SUDO=
fi
echo "install-deps: installing ${#missing[@]} packages ($*): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
