#!/usr/bin/env bash
# The one place that installs the Debian 12 packages shadowbench needs, in groups:
#   bench  the toolchain and the libraries the bench program builds against and runs on (quick start 1,
#          scripts/bench.sh): enough for every measuring subcommand
#   plot   python3 with matplotlib and pandas: `bench figures` (tools/plot.py) and `bench report`
#          (tools/report.py), optional at run time (without them those two stop with an error naming
#          what to install)
#   driver the second GL and Vulkan driver, Mesa 25.0.7 from Debian's bookworm-backports suite, unpacked
#          (not installed: the system's Mesa stays the default) into its own prefix,
#          <drivers>/mesa-25.0.7 (<drivers>: $SHADOWBENCH_DRIVERS_DIR, else /opt/shadowbench/drivers),
#          for `bench --driver mesa-25.0.7` (core/DriverTable.h); adds the suite to apt's sources if
#          missing. About 24 MB downloaded, 119 MB unpacked, 12-19 s
#   slurm  Slurm 22.05 (slurmctld, slurmd, the client commands) and munge: a real single-node cluster
#          started by hand, without systemd, by tools/slurm/cluster.sh (the launcher's test,
#          tests/JobArraySlurmTest.cpp, and trying scripts/slurm-sweep.sbatch). The packages' own
#          services are not used; where an init system starts them, they keep to their default ports
#          and sockets, apart from the test's cluster
#   perf   the peer comparison with glmark2's shadow scene (results/perf/README.md,
#          tools/perf/glmark2-compare.sh): glmark2 and its models, Xvfb for it, apitrace to trace and replay
#          it, valgrind to count its instructions; not part of test (CI does not run the comparison)
#   test   everything: bench, plot, driver, slurm, and what the test suite, the sanitizer build and the
#          fuzzers drive (quick start 2, scripts/test.sh); the default
# Idempotent: packages already present are skipped and a complete driver prefix is kept, so it costs
# ~1 s on a provisioned machine. Needs root (apt-get). Usage: bash scripts/install-deps.sh [GROUP]...
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
SLURM=(
  # slurm-wlm: slurmctld, slurmd and slurm-client (sbatch, scontrol, squeue, scancel, sinfo); munge
  # comes with slurmd, named here because tools/slurm/cluster.sh starts munged itself
  slurm-wlm munge
)
PERF=(
  # glmark2 (the X11 build: it renders off-screen under Xvfb) and its models (horse.3ds, which
  # results/perf/horse.json names)
  glmark2-x11 glmark2-data
  # Xvfb and xvfb-run (which needs xauth) for glmark2's X display
  xvfb xauth
  # apitrace traces glmark2 and glretrace replays it (apitrace-tracers: the wrapper libraries `apitrace
  # trace` preloads; python3-pil: apitrace's image tools)
  apitrace apitrace-tracers python3-pil
  # instructions per frame of both programs (callgrind, callgrind_annotate)
  valgrind
  # the comparison script's ratios and its parsing of bench's CSV
  bc python3
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

# The second driver: Debian's packages of this Mesa release, at this exact version, unpacked together.
DRIVER_NAME=mesa-25.0.7
DRIVER_VERSION=25.0.7-2~bpo12+1
DRIVER_SUITE=bookworm-backports
DRIVER_DEBS=(mesa-libgallium libgl1-mesa-dri libegl-mesa0 libglx-mesa0 libgbm1 libosmesa6 mesa-vulkan-drivers)
# The libdrm the backport was built against: bookworm's 2.4.114 lacks symbols libgallium names
# (amdgpu_va_get_start_addr), harmless while symbols bind lazily, fatal under LD_BIND_NOW=1 (the perf
# gate's layer B pins it).
DRM_VERSION=2.4.123-1~bpo12+1
DRM_DEBS=(libdrm2 libdrm-amdgpu1)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; return; fi
  command -v sudo >/dev/null || { echo "install-deps: need root to run: $*" >&2; exit 1; }
  sudo "$@"
}

# A deb822 source for the backports suite, beside the bookworm one Debian's image carries.
ensure_backports_source() {
  if grep -rqs "$DRIVER_SUITE" /etc/apt/sources.list /etc/apt/sources.list.d/; then return; fi
  echo "install-deps: adding Debian's $DRIVER_SUITE suite to apt's sources"
  printf 'Types: deb\nURIs: http://deb.debian.org/debian\nSuites: %s\nComponents: main\nSigned-By: %s\n' \
    "$DRIVER_SUITE" /usr/share/keyrings/debian-archive-keyring.gpg |
    as_root tee "/etc/apt/sources.list.d/$DRIVER_SUITE.sources" >/dev/null
}

# Complete: the stamp names this version, or (a prefix laid out by hand, which may lack the libdrm that
# only layer B needs) the versioned gallium library and both files the driver table reads are there.
driver_complete() {
  local prefix=$1 lib=$1/usr/lib/x86_64-linux-gnu
  [ "$(cat "$prefix/.shadowbench-driver" 2>/dev/null)" = "$DRIVER_VERSION" ] && return 0
  [ -f "$lib/libgallium-$DRIVER_VERSION.so" ] && [ -f "$prefix/etc/egl_vendor.json" ] &&
    [ -f "$prefix/etc/lvp_icd.json" ]
}

install_driver() {
  local drivers=${SHADOWBENCH_DRIVERS_DIR:-/opt/shadowbench/drivers}
  local prefix=$drivers/$DRIVER_NAME
  if driver_complete "$prefix"; then
    echo "install-deps: driver $DRIVER_NAME ($DRIVER_VERSION) present in $prefix"
    return
  fi
  ensure_backports_source
  local pinned=()
  for p in "${DRIVER_DEBS[@]}"; do pinned+=("$p=$DRIVER_VERSION"); done
  for p in "${DRM_DEBS[@]}"; do pinned+=("$p=$DRM_VERSION"); done
  # apt-cache show exits 0 for a version it does not know as long as it knows the package (bookworm
  # carries mesa-vulkan-drivers 22.3.6), so ask whether it printed the record: on a fresh machine the
  # suite just added has no package lists yet.
  if ! apt-cache show "mesa-vulkan-drivers=$DRIVER_VERSION" 2>/dev/null | grep -q '^Package:'; then
    as_root apt-get update -qq
  fi
  echo "install-deps: downloading Mesa $DRIVER_VERSION (${DRIVER_DEBS[*]}; ${DRM_DEBS[*]} $DRM_VERSION) into $prefix"
  mkdir -p "$drivers"
  local tmp
  tmp=$(mktemp -d "$drivers/.$DRIVER_NAME.XXXXXX")
  trap 'rm -rf "$tmp"' EXIT
  if ! (cd "$tmp" && apt-get download -q "${pinned[@]}" >/dev/null 2>"$tmp/apt.log"); then
    echo "install-deps: cannot download Mesa $DRIVER_VERSION from $DRIVER_SUITE: $(grep -m1 '^E:' "$tmp/apt.log" || tail -n1 "$tmp/apt.log")" >&2
    exit 1
  fi
  for deb in "$tmp"/*.deb; do dpkg -x "$deb" "$tmp/prefix"; done
  # The files the loaders read, naming the libraries by absolute path (the packages' own name them by
  # file name, for the system's library path): glvnd's EGL vendor file and lavapipe's ICD file.
  local lib=$prefix/usr/lib/x86_64-linux-gnu
  mkdir -p "$tmp/prefix/etc"
  printf '{"file_format_version":"1.0.0","ICD":{"library_path":"%s"}}' "$lib/libEGL_mesa.so.0" \
    >"$tmp/prefix/etc/egl_vendor.json"
  sed "s|\"library_path\": \"libvulkan_lvp.so\"|\"library_path\": \"$lib/libvulkan_lvp.so\"|" \
    "$tmp/prefix/usr/share/vulkan/icd.d/lvp_icd.json" >"$tmp/prefix/etc/lvp_icd.json"
  grep -q "\"$lib/libvulkan_lvp.so\"" "$tmp/prefix/etc/lvp_icd.json" || {
    echo "install-deps: lavapipe's ICD file in Mesa $DRIVER_VERSION has an unexpected library_path" >&2
    exit 1
  }
  echo "$DRIVER_VERSION" >"$tmp/prefix/.shadowbench-driver"
  rm -rf "$prefix"
  mv "$tmp/prefix" "$prefix"
  rm -rf "$tmp"
  trap - EXIT
  echo "install-deps: driver $DRIVER_NAME in $prefix ($(du -sm "$prefix" | cut -f1) MB)"
}

[ $# -eq 0 ] && set -- test
PACKAGES=()
WANT_DRIVER=0
for group in "$@"; do
  case "$group" in
    bench) PACKAGES+=("${BENCH[@]}") ;;
    plot) PACKAGES+=("${PLOT[@]}") ;;
    driver) WANT_DRIVER=1 ;;
    slurm) PACKAGES+=("${SLURM[@]}") ;;
    perf) PACKAGES+=("${PERF[@]}") ;;
    test) PACKAGES+=("${BENCH[@]}" "${PLOT[@]}" "${SLURM[@]}" "${TEST[@]}"); WANT_DRIVER=1 ;;
    *) echo "install-deps: unknown group '$group' (bench, plot, driver, slurm, perf or test)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  [ ${#PACKAGES[@]} -gt 0 ] && echo "install-deps: all ${#PACKAGES[@]} packages of '$*' present"
else
  echo "install-deps: installing ${#missing[@]} packages ($*): ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  as_root apt-get update -qq
  as_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  echo "install-deps: done"
fi
[ $WANT_DRIVER -eq 0 ] || install_driver
