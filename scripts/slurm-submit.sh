#!/usr/bin/env bash
# Submits a sweep to Slurm: the job array of its shards (scripts/slurm-sweep.sbatch) and the merge job,
# which runs once every task has ended, whatever the outcome (--dependency=afterany: afterok would
# never run after a failed or timed-out task), and says which shards are missing. Prints both job ids.
# The jobs run in the current folder (their logs go there; build/bench is found there unless
# SHADOWBENCH_BENCH names it): run it from the project root.
#
# Usage: bash scripts/slurm-submit.sh SBATCH_OPTIONS... -- [--shards N] SWEEP.json OUT_PREFIX [SWEEP_ARGS...]
#   SBATCH_OPTIONS go to the array's sbatch and must include --array=SPEC; the merge job gets the same
#   --partition, --account and --qos. After `--` come scripts/slurm-sweep.sbatch's arguments (see its
#   header: shards, GPUs, requeue, exit codes).
# Examples:
#   bash scripts/slurm-submit.sh --array=1-8 -c 4 --mem=4G -- sweeps/submission.json out/sub
#   bash scripts/slurm-submit.sh --array=0-15%4 -p gpu --gres=gpu:1 -- sweeps/quality.json out/q --frames 5
#   bash scripts/slurm-submit.sh --array=3 -- sweeps/submission.json out/sub     # index 3 again, then merge
# Output (the ids and where the logs go):
#   slurm-submit: array job 41 (shards of out/sub): logs shadowbench-sweep-41_<index>.log
#   slurm-submit: merge job 42 after any outcome of 41: writes out/sub.csv, log shadowbench-merge-42.log
# Before submitting, the sweep is checked with `bench sweep ... --dry-run` here, so that bad input
# (exit 2) is refused now rather than by every task.
# Exit codes: 0 submitted, 2 wrong input (arguments, the sweep), 3 no sbatch or no bench, 1 sbatch
# refused (its message is printed).
set -euo pipefail

readonly kUsage="usage: bash scripts/slurm-submit.sh SBATCH_OPTIONS... -- [--shards N] SWEEP.json OUT_PREFIX [SWEEP_ARGS...]"
kScript=$(dirname "${BASH_SOURCE[0]}")/slurm-sweep.sbatch
readonly kScript
bench=${SHADOWBENCH_BENCH:-build/bench}

die() {
  local code=$1
  shift
  echo "slurm-submit: $*" >&2
  exit "$code"
}

array_options=()
merge_options=()
has_array=0
job_name=shadowbench-sweep
while [ $# -gt 0 ] && [ "$1" != -- ]; do
  case "$1" in
    --array=* | -a?* | --array | -a) has_array=1 ;;
    --job-name=*) job_name=${1#--job-name=} ;;
    --job-name | -J) job_name=${2:-} ;;
    -J?*) job_name=${1#-J} ;;
  esac
  # The options the merge job shares: where it runs and who pays.
  case "$1" in
    --partition=* | --account=* | --qos=* | -p?* | -A?*) merge_options+=("$1") ;;
    --partition | --account | --qos | -p | -A) [ $# -ge 2 ] && merge_options+=("$1" "$2") ;;
  esac
  case "$1" in
    --array | -a | --partition | --account | --qos | -p | -A | -c | --cpus-per-task | --mem | -t | --time | \
      --gres | -J | --job-name | -o | --output | -d | --dependency | -w | --nodelist | -C | --constraint)
      [ $# -ge 2 ] || die 2 "$1 needs a value: $kUsage"
      array_options+=("$1" "$2")
      shift 2
      ;;
    *)
      array_options+=("$1")
      shift
      ;;
  esac
done
[ "${1:-}" = -- ] || die 2 "no -- between the sbatch options and the sweep's arguments: $kUsage"
shift
[ "$has_array" = 1 ] || die 2 "no --array=SPEC among the sbatch options: $kUsage"
sweep=("$@")
# The sweep's own arguments: [--shards N] SWEEP.json OUT_PREFIX [SWEEP_ARGS...].
at=0
case "${sweep[0]:-}" in
  --shards) at=2 ;;
  --shards=*) at=1 ;;
esac
[ ${#sweep[@]} -ge $((at + 2)) ] || die 2 "$kUsage"
definition=${sweep[$at]}
prefix=${sweep[$((at + 1))]}
[ -f "$definition" ] || die 2 "no sweep definition $definition (in $(pwd))"
command -v sbatch >/dev/null || die 3 "no sbatch on PATH: this machine is not a Slurm submission host"
[ -x "$bench" ] || die 3 "no bench program at $bench (build it, or set SHADOWBENCH_BENCH)"
if ! check=$("$bench" sweep "$definition" "${sweep[@]:$((at + 2))}" --dry-run 2>&1 >/dev/null); then
  die 2 "the sweep is refused by bench sweep --dry-run: $check"
fi

submit() {
  local out
  out=$(sbatch --parsable "$@" 2>&1) || die 1 "sbatch refused: $out"
  echo "${out%%;*}"
}

array_job=$(submit "${array_options[@]}" "$kScript" "${sweep[@]}")
echo "slurm-submit: array job $array_job (shards of $prefix): logs ${job_name}-${array_job}_<index>.log"
merge_job=$(submit "${merge_options[@]}" --dependency="afterany:$array_job" --job-name=shadowbench-merge \
  --output=%x-%j.log "$kScript" --merge "$prefix")
echo "slurm-submit: merge job $merge_job after any outcome of $array_job: writes $prefix.csv, log shadowbench-merge-$merge_job.log"
