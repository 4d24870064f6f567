#!/usr/bin/env bash
# Builds the fuzz targets of the asan preset (clang 14, libFuzzer + ASan + UBSan, build-asan/, the tree
# scripts/sanitize.sh builds its tests in, so after it only the targets link) and runs every target of
# fuzz/ (docs/ARCHITECTURE.md, "Fuzzing and sanitizers"):
#   1. the reach check: the target runs once on each input of fuzz/reach/<target>/ and must come to the
#      outcome the file's name states (parsed.* parses, rejected.* ends in the parser's sb::Error), so
#      a fuzzer that cannot get into its parser fails here instead of reporting empty executions; then
#      once on each input of fuzz/regressions/<target>/ (crashes found and fixed), which must not crash;
#   2. libFuzzer for SECONDS (default 60) each, from a copy of fuzz/corpus/<target>/ in
#      build-asan/fuzz-runs/<target>/ (the committed corpus never grows in CI), targets in parallel, one
#      per core.
# Prints executions and coverage per target and exits non-zero when a reach check fails or a fuzzer
# crashes, naming the input it wrote. Fuzz longer: bash scripts/fuzz.sh 3600; one target:
# SB_FUZZ_TARGETS=scene_loader bash scripts/fuzz.sh 600.
# Usage: bash scripts/fuzz.sh [seconds]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
targets=(${SB_FUZZ_TARGETS:-scene_loader technique_spec sweep_definition csv_parse})

# SHADOWBENCH_DEPS_CHECKED=1: the caller (scripts/test.sh) has just run it.
[ "${SHADOWBENCH_DEPS_CHECKED:-0}" = 1 ] || bash "$root/scripts/install-deps.sh"
# shellcheck source=tools/sanitizers/options.sh
source "$root/tools/sanitizers/options.sh"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cd "$root"
start=$SECONDS
cmake --preset asan "${launcher[@]}" >/dev/null
cmake --build build-asan --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
echo "fuzz: build: $((SECONDS - start)) s"

runs="$root/build-asan/fuzz-runs"
failed=0

# ---- 1. reach check and regressions ------------------------------------------------------------------
declare -A reach
for t in "${targets[@]}"; do
  bin="$root/build-asan/fuzz/fuzz_$t"
  reach[$t]=ok
  inputs=("$root"/fuzz/reach/"$t"/*)
  if [ ! -e "${inputs[0]}" ]; then
    echo "fuzz: $t: no inputs in fuzz/reach/$t/" >&2
    reach[$t]=FAILED
    continue
  fi
  for f in "$root"/fuzz/reach/"$t"/* "$root"/fuzz/regressions/"$t"/*; do
    [ -f "$f" ] || continue
    case "$(basename "$f")" in
      parsed.*) expect=parsed ;;
      rejected.*) expect=rejected ;;
      *) expect= ;; # a regression: any outcome but a crash
    esac
    if ! out="$(SB_FUZZ_EXPECT="$expect" "$bin" -close_fd_mask=1 "$f" 2>&1)"; then
      echo "fuzz: $t: ${f#"$root"/} ${expect:+(expected: $expect)} FAILED:" >&2
      printf '%s\n' "$out" | grep -v '^INFO:\|^\*\*\*\|^Running:\|^Executed' | tail -40 >&2
      reach[$t]=FAILED
    fi
  done
  [ "${reach[$t]}" = ok ] || failed=1
done

# ---- 2. fuzzing ------------------------------------------------------------------------------------
run_one() {
  local t="$1" dir="$runs/$1"
  rm -rf "$dir"
  mkdir -p "$dir/corpus"
  cp "$root"/fuzz/corpus/"$t"/* "$dir/corpus/"
  local dict=()
  [ -f "$root/fuzz/$t.dict" ] && dict=(-dict="$root/fuzz/$t.dict")
  # -max_len 4096: larger inputs add nothing the parsers do not see in 4 KiB (deep nesting is bounded by
  # JsonReader's pre-scan and pinned by SceneLoaderTest).
  local rc=0
  "$root/build-asan/fuzz/fuzz_$t" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
    -rss_limit_mb=2048 -max_len=4096 -close_fd_mask=1 -artifact_prefix="$dir/" "${dict[@]}" \
    "$dir/corpus" >"$dir/log" 2>&1 || rc=$?
  echo "$rc" >"$dir/rc"
}
start=$SECONDS
jobs_running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  jobs_running=$((jobs_running + 1))
  if [ "$jobs_running" -ge "$(nproc)" ]; then
    wait -n
    jobs_running=$((jobs_running - 1))
  fi
done
wait
echo "fuzz: fuzzing: $((SECONDS - start)) s ($seconds s per target)"

printf '\n%-18s %-7s %10s %8s %7s %7s  %s\n' target reach execs exec/s cov ft result
for t in "${targets[@]}"; do
  dir="$runs/$t"
  rc="$(cat "$dir/rc")"
  # The last status line ("#1234 DONE cov: 812 ft: 3050 ..." or the last before a crash).
  status_line="$(grep -E '^#[0-9]+' "$dir/log" | tail -1 || true)"
  cov="$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$status_line")"
  ft="$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$status_line")"
  execs="$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$dir/log" | tail -1)"
  rate="$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+)/\1/p' "$dir/log" | tail -1)"
  if [ "$rc" = 0 ]; then
    result=ok
  else
    failed=1
    artifact="$(sed -nE 's/.*Test unit written to (.*)$/\1/p' "$dir/log" | tail -1)"
    result="CRASH (exit $rc): ${artifact:-see $dir/log}"
  fi
  printf '%-18s %-7s %10s %8s %7s %7s  %s\n' "$t" "${reach[$t]}" "${execs:--}" "${rate:--}" "${cov:--}" \
    "${ft:--}" "$result"
done
for t in "${targets[@]}"; do
  dir="$runs/$t"
  [ "$(cat "$dir/rc")" = 0 ] && continue
  echo
  echo "fuzz: $t crashed; the report ($dir/log):"
  grep -vE '^#[0-9]+|^INFO:' "$dir/log" | tail -60
  echo "fuzz: reproduce: build-asan/fuzz/fuzz_$t <the input above>; once fixed, commit the input under fuzz/regressions/$t/"
done
exit $failed
