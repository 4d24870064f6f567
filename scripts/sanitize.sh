#!/usr/bin/env bash
# Builds the asan preset (clang 14, AddressSanitizer + UndefinedBehaviorSanitizer, -O1 -g1, in build-asan/,
# the tree scripts/fuzz.sh builds its targets in)
# and runs the tests of the given ctest labels under it (default: unit cli vulkan), with the options and the
# library-leak suppressions of tools/sanitizers/. Only the test binaries of those labels, bench, handloop
# and handshadow are built. Any sanitizer report fails the test that triggered it, so the script fails too.
# The cli label is the exception to "built under ASan": its tests only start bench (or handshadow) and
# read what it wrote, so the release build's test binaries (build/, built here if missing) run against
# build-asan's bench through SHADOWBENCH_TEST_BENCH (tests/TestPaths.h). Their reports go to files
# (log_path), and any report file fails the label whatever exit code the test expected (about 160 s of CI
# that compiling 31 test files a second time cost).
# Usage: bash scripts/sanitize.sh [label ...]     e.g. bash scripts/sanitize.sh unit cli gl
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
labels=("$@")
[ ${#labels[@]} -gt 0 ] || labels=(unit cli vulkan)

# SHADOWBENCH_DEPS_CHECKED=1: the caller (scripts/test.sh) has just run it.
[ "${SHADOWBENCH_DEPS_CHECKED:-0}" = 1 ] || bash "$root/scripts/install-deps.sh"
# The options the runs get, also during the build: gtest_discover_tests runs each test binary to list
# its tests, and a leak report there would fail the build instead of the test.
# shellcheck source=tools/sanitizers/options.sh
source "$root/tools/sanitizers/options.sh"

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cd "$root"
start=$SECONDS
cmake --preset asan "${launcher[@]}" >/dev/null
# The test binaries a label needs: tests/CMakeLists.txt labels every test target and writes the list,
# one "<target> <label>" a line, to build-asan/tests/TestLabels.txt when it configures. The cli label's
# binaries come from the release build (see above).
targets=(bench handloop handshadow sb_man_and_completion)
cli_targets=()
while read -r name label; do
  for want in "${labels[@]}"; do
    [ "$want" = "$label" ] || continue
    if [ "$label" = cli ]; then cli_targets+=("$name"); else targets+=("$name"); fi
  done
done <build-asan/tests/TestLabels.txt
cmake --build build-asan --parallel "$(nproc)" --target "${targets[@]}"
echo "sanitize: build ${#targets[@]} targets: $((SECONDS - start)) s"
if [ ${#cli_targets[@]} -gt 0 ]; then
  # After scripts/test.sh these are built already and this is a no-op.
  [ -f build/build.ninja ] || cmake --preset release "${launcher[@]}" >/dev/null
  cmake --build build --parallel "$(nproc)" --target "${cli_targets[@]}"
fi

cd "$root/build-asan"
# Like scripts/test.sh: without a display, Xvfb, so the GLFW backend is tested too.
wrap=()
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  wrap=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
# The tests left out of every sanitizer run, and why: tools/sanitizers/left-out.sh.
# shellcheck source=tools/sanitizers/left-out.sh
source "$root/tools/sanitizers/left-out.sh"
exclude=$SB_SANITIZE_LEFT_OUT
status=0
summary=()
# The cli label: build/'s test binaries, build-asan's programs, every sanitizer report written to a file
# of $reports (LeakSanitizer's too) so that none hides behind an exit code a test expected anyway.
run_cli() {
  local reports="$root/build-asan/sanitizer-reports"
  rm -rf "$reports"
  mkdir -p "$reports"
  local rc=0
  (cd "$root/build" &&
    SHADOWBENCH_TEST_BENCH="$root/build-asan/bench" SHADOWBENCH_TEST_HANDSHADOW="$root/build-asan/handshadow" \
      ASAN_OPTIONS="$ASAN_OPTIONS:log_path=$reports/asan" UBSAN_OPTIONS="$UBSAN_OPTIONS:log_path=$reports/ubsan" \
      "${wrap[@]}" ctest --output-on-failure --parallel "$(nproc)" -L '^cli$' -E "$exclude") || rc=$?
  if compgen -G "$reports/*" >/dev/null; then
    echo "sanitize: sanitizer reports from the cli tests' bench processes:" >&2
    for f in "$reports"/*; do
      echo "---- $f" >&2
      head -60 "$f" >&2
    done
    rc=1
  fi
  return $rc
}
for label in "${labels[@]}"; do
  start=$SECONDS
  rc=0
  if [ "$label" = cli ]; then
    run_cli || rc=$?
  else
    "${wrap[@]}" ctest --output-on-failure --parallel "$(nproc)" -L "^${label}\$" -E "$exclude" || rc=$?
  fi
  summary+=("$(printf '%-6s %5d s  %s' "$label" $((SECONDS - start)) "$([ $rc -eq 0 ] && echo ok || echo FAILED)")")
  [ $rc -eq 0 ] || status=1
done
# Under the other SIMD width llvmpipe runs, 128 bits (CPUs without AVX, and ARM; this machine's default
# is 256): every registered technique and -t auto once, one frame at 32x32, in one ASan bench process, on
# the same shader cache as the runs above (the case core/DriverShaderCache.h keeps apart).
start=$SECONDS
rc=0
# A technique without a GL form (bench --list: "apis: vulkan (no GL form: ...)", raytraced) runs on Vulkan
# on the second driver, whose lavapipe has what it needs (the test group installs it).
mapfile -t techniques < <(./bench --list | awk '/^scenes:/ {exit} /^[a-z]/ {name=$1} /apis: *gl/ {print "-t"; print name}')
mapfile -t vk_only < <(./bench --list | awk '/^scenes:/ {exit} /^[a-z]/ {name=$1} /apis:.*no GL form/ {print "-t"; print name}')
LP_NATIVE_VECTOR_WIDTH=128 ./bench "${techniques[@]}" -t auto --instances 2 --size 32x32 --frames 1 \
  --no-timer-check >/dev/null || rc=$?
if [ ${#vk_only[@]} -gt 0 ]; then
  LP_NATIVE_VECTOR_WIDTH=128 ./bench --driver mesa-25.0.7 --api vulkan "${vk_only[@]}" --instances 2 \
    --size 32x32 --frames 1 --no-timer-check >/dev/null || rc=$?
fi
summary+=("$(printf '%-6s %5d s  %s' lp128 $((SECONDS - start)) "$([ $rc -eq 0 ] && echo ok || echo FAILED)")")
[ $rc -eq 0 ] || status=1
# Every technique with a Vulkan form (bench --list: "apis: gl, vulkan"), retained and instanced, on
# lavapipe with the validation layer on: a validation error or a sanitizer report fails the step.
start=$SECONDS
rc=0
mapfile -t vk_techniques < <(./bench --list | awk '/^scenes:/ {exit} /^[a-z]/ {name=$1} /apis: *gl, vulkan/ {print "-t"; print name}')
for mode in retained instanced; do
  ./bench --api vulkan --vk-validation "${vk_techniques[@]}" --submit "$mode" --instances 2 --size 32x32 \
    --frames 1 --no-timer-check >/dev/null 2>vkall.log || { rc=$?; cat vkall.log; }
  # The techniques with a Vulkan form only, on the driver that runs them (vk_only above).
  if [ ${#vk_only[@]} -gt 0 ]; then
    ./bench --driver mesa-25.0.7 --api vulkan --vk-validation "${vk_only[@]}" --submit "$mode" --instances 2 \
      --size 32x32 --frames 1 --no-timer-check >/dev/null 2>vkall.log || { rc=$?; cat vkall.log; }
  fi
done
# The matrix's variants (bench --list: "matrix: variants ...") and contact=true on every member that
# declares it, in one process per driver, retained: a variant's shaders are not its default's, and a
# driver can leak on what only they contain (lavapipe 22.3.6's draw-time shader variants, which a branch of
# contact_shadow.glsl once triggered: shaders/common/contact_shadow.glsl). On the system driver a refusal
# (exit 3: what it lacks, raytraced's ray queries, mesh shaders, sparse residency) is allowed, since every
# spec must then run on the second driver; a sanitizer report or a validation error exits 1 either way.
mapfile -t variants < <(./bench --list | awk '
  function add(spec) { if (vk && !(spec in seen)) { seen[spec] = 1; print "-t"; print spec } }
  /^scenes:/ {exit}
  /^[a-z]/ {name = $1; vk = 0}
  /^  apis:/ {vk = ($0 ~ /vulkan/)}
  /^  contact +bool/ {add(name ":contact=true")}
  /^  matrix: *variants/ {s = $0; while (match(s, /[a-z_]+=[A-Za-z0-9_.]+ \(rule/)) {
    add(name ":" substr(s, RSTART, RLENGTH - 6)); s = substr(s, RSTART + RLENGTH)}}')
if [ ${#variants[@]} -gt 0 ]; then
  vrc=0
  ./bench --api vulkan --vk-validation "${variants[@]}" --instances 2 --size 32x32 --frames 1 \
    --no-timer-check >/dev/null 2>vkall.log || vrc=$?
  if [ $vrc -ne 0 ] && [ $vrc -ne 3 ]; then rc=$vrc; cat vkall.log; fi
  ./bench --driver mesa-25.0.7 --api vulkan --vk-validation "${variants[@]}" --instances 2 --size 32x32 \
    --frames 1 --no-timer-check >/dev/null 2>vkall.log || { rc=$?; cat vkall.log; }
fi
summary+=("$(printf '%-6s %5d s  %s' vkall $((SECONDS - start)) "$([ $rc -eq 0 ] && echo ok || echo FAILED)")")
[ $rc -eq 0 ] || status=1
echo "sanitize: ctest under ASan + UBSan (build-asan/), every technique at 128-bit vectors (lp128), every"
echo "  Vulkan form and matrix variant under the validation layer (vkall)"
printf '  %s\n' "${summary[@]}"
exit $status
