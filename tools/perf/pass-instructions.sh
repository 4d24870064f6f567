#!/usr/bin/env bash
# Instructions of a traced GL program's replay under callgrind, split by tools/perf/callgrind_objects.py
# into the JIT-compiled shaders, Mesa, the replayer and the rest. Instructions per frame are the
# difference of two traces of the same run with N and 2N frames, divided by N (the set-up, shader
# compiles and teardown cancel). With --ignore-pass K the replay skips the draws of the frames' K-th pass
# (tools/perf/trace_passes.py finds them), so the difference against the full replay is that pass's
# price, its rasterisation and shaders included. The same replayer runs both programs' traces, so both
# are counted alike; llvmpipe is pinned (LP_NUM_THREADS=0: every triangle is rasterised on the counted
# thread) and the shader cache is off. (A dump per frame does not work: the replayer reaches glFinish
# through Mesa's dispatch, which has no symbol for callgrind's --dump-before.)
# results/perf/README.md gives the numbers and the commands.
set -euo pipefail

usage() {
    cat <<'EOF'
Usage: tools/perf/pass-instructions.sh --trace FILE --out DIR [options]

Replays FILE under callgrind and prints its instructions by where the code lives.

Options:
  --trace FILE      an apitrace trace (apitrace trace --output FILE ...)
  --out DIR         where the dumps go (created; must not exist or be empty)
  --api glx|egl     the trace's window system: glx (glmark2 under Xvfb, replayed by glretrace under
                    xvfb-run) or egl (bench, replayed by eglretrace on surfaceless EGL)  [glx]
  --ignore-pass K   skip the draws of pass K (0-based, in frame order) of every frame
  --driver PREFIX   a Mesa prefix (as bench --driver takes a path) for the replay  [the system's]
  -h, --help        this text

Examples:
  tools/perf/pass-instructions.sh --trace /tmp/glmark2-4.trace --out /tmp/cg-g4
  tools/perf/pass-instructions.sh --trace /tmp/glmark2-8.trace --out /tmp/cg-g8   # per frame: (g8 - g4) / 4
  tools/perf/pass-instructions.sh --trace /tmp/glmark2-8.trace --out /tmp/cg-g8-nodepth --ignore-pass 0
  tools/perf/pass-instructions.sh --api egl --trace /tmp/bench-8.trace --out /tmp/cg-b8
EOF
}

die() {
    echo "pass-instructions: $2" >&2
    exit "$1"
}

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
trace="" out="" api=glx pass="" prefix=""
while [ $# -gt 0 ]; do
    case "$1" in
    -h | --help) usage; exit 0 ;;
    --trace | --out | --api | --ignore-pass | --driver)
        [ $# -ge 2 ] || die 2 "$1: expected a value (see --help)"
        case "$1" in
        --trace) trace=$2 ;;
        --out) out=$2 ;;
        --api) api=$2 ;;
        --ignore-pass) pass=$2 ;;
        --driver) prefix=$2 ;;
        esac
        shift 2 ;;
    *) die 2 "unknown option '$1' (see --help)" ;;
    esac
done
[ -n "$trace" ] || die 2 "--trace: required (see --help)"
[ -f "$trace" ] || die 2 "--trace $trace: no such file"
[ -n "$out" ] || die 2 "--out: required (see --help)"
[ -z "$pass" ] || [[ "$pass" =~ ^[0-9]+$ ]] || die 2 "--ignore-pass: expected a pass number, got '$pass'"
case "$api" in glx) replayer=glretrace ;; egl) replayer=eglretrace ;; *) die 2 "--api: glx or egl, got '$api'" ;; esac
for tool in valgrind "$replayer" apitrace python3; do
    command -v "$tool" >/dev/null || die 3 "$tool is not installed: bash scripts/install-deps.sh perf"
done
[ "$api" = egl ] || command -v xvfb-run >/dev/null || die 3 "xvfb-run is not installed: bash scripts/install-deps.sh perf"
if [ -e "$out" ] && [ -n "$(ls -A "$out")" ]; then die 2 "--out $out: not empty (the dumps would mix)"; fi
mkdir -p "$out"

env_vars=(LP_NUM_THREADS=0 MESA_SHADER_CACHE_DISABLE=true)
if [ -n "$prefix" ]; then
    lib=$prefix/usr/lib/x86_64-linux-gnu
    [ -d "$lib" ] || die 2 "--driver $prefix: no usr/lib/x86_64-linux-gnu in it"
    env_vars+=("LD_LIBRARY_PATH=$lib" "LIBGL_DRIVERS_PATH=$lib/dri")
    [ -f "$prefix/etc/egl_vendor.json" ] && env_vars+=("__EGL_VENDOR_LIBRARY_FILENAMES=$prefix/etc/egl_vendor.json")
fi
[ "$api" = egl ] && env_vars+=(WAFFLE_PLATFORM=surfaceless_egl)

ignore=""
if [ -n "$pass" ]; then
    ignore=$(apitrace dump --color=never "$trace" | python3 "$root/tools/perf/trace_passes.py" --ignore "$pass" --ignore-draws) ||
        die 2 "--ignore-pass $pass: not a pass of this trace's frames"
    echo "pass-instructions: skipping calls $ignore" >&2
fi
cmd=(valgrind --tool=callgrind --smc-check=all-non-file "--callgrind-out-file=$out/callgrind.out.%p"
    "$replayer" --benchmark)
[ "$api" = egl ] && cmd+=(--headless)
[ -n "$ignore" ] && cmd+=("--ignore-calls=$ignore")
cmd+=("$trace")
[ "$api" = glx ] && cmd=(xvfb-run -a -s "-screen 0 1280x1024x24" "${cmd[@]}")
echo "pass-instructions: ${env_vars[*]} ${cmd[*]}" >&2
env "${env_vars[@]}" "${cmd[@]}" >"$out/replay.log" 2>&1 || {
    tail -n 5 "$out/replay.log" >&2
    die 1 "the replay failed (log: $out/replay.log)"
}
python3 "$root/tools/perf/callgrind_objects.py" "$out"/callgrind.out.*
