#!/usr/bin/env bash
# A real single-node Slurm cluster on this machine, for the launcher's test (tests/JobArraySlurmTest.cpp)
# and for trying scripts/slurm-sweep.sbatch before a real cluster: munged, slurmctld and slurmd from
# Debian's packages (`bash scripts/install-deps.sh slurm`), started by hand as root without systemd.
# Everything lives in one folder DIR: the munge key and socket, slurm.conf, the controller's state, the
# daemons' spool, pid files and logs. The daemons listen on two free TCP ports of 127.0.0.1 found at
# start, so the cluster stays apart from a Slurm the machine may run already.
#
# Usage:
#   bash tools/slurm/cluster.sh start DIR [--owner PID]   start the cluster in DIR (created); with --owner
#                                                         it is stopped when process PID ends
#   bash tools/slurm/cluster.sh stop DIR                  cancel every job, stop the daemons; DIR stays
#   bash tools/slurm/cluster.sh run DIR -- COMMAND...     start, run COMMAND with SLURM_CONF set, stop;
#                                                         exits with COMMAND's code
# Examples:
#   bash tools/slurm/cluster.sh start /tmp/sb-slurm && export SLURM_CONF=/tmp/sb-slurm/slurm.conf
#   sbatch --array=1-2 scripts/slurm-sweep.sbatch sweeps/submission.json out/sub --size 64x64 --frames 2
#   bash tools/slurm/cluster.sh stop /tmp/sb-slurm
#   bash tools/slurm/cluster.sh run /tmp/sb-slurm -- bash -c 'sinfo && squeue'
#
# The cluster: one node (this machine, as `slurmd -C` describes it) in partition `debug`; CPUs are the
# consumable (select/cons_tres, CR_CPU), task/affinity binds each job to its CPUs, processes are tracked
# by proctrack/linuxproc (no cgroup needed), no accounting database (`sacct` is not available): finished
# jobs stay visible to `scontrol show job` for an hour (MinJobAge) and are logged to DIR/jobcomp.txt.
# The scheduler runs every second and at once on submission, so a test's jobs start within a second.
# Exit codes: 0 done, 2 wrong usage, 3 not root or a package missing (the message names the install
# command), 1 a daemon did not come up (the message names its log).
set -euo pipefail

readonly kInstall="bash scripts/install-deps.sh slurm"
readonly kMarker=SHADOWBENCH_SLURM_CLUSTER # in the daemons' environment: `stop` finds their processes by it

die() {
  local code=$1
  shift
  echo "tools/slurm/cluster.sh: $*" >&2
  exit "$code"
}

require_machine() {
  [ "$(id -u)" -eq 0 ] || die 3 "the daemons run as root: run as root (and install with: $kInstall)"
  local missing=()
  for c in munged slurmctld slurmd sbatch scontrol squeue scancel sinfo; do
    command -v "$c" >/dev/null 2>&1 || [ -x "/usr/sbin/$c" ] || missing+=("$c")
  done
  [ ${#missing[@]} -eq 0 ] || die 3 "missing ${missing[*]}: install them with: $kInstall"
}

# A daemon's program: on PATH, else in /usr/sbin (not on a plain user's PATH).
program() {
  command -v "$1" 2>/dev/null || echo "/usr/sbin/$1"
}

# A TCP port of 127.0.0.1 nobody listens on (a connection attempt that fails), other than $1.
free_port() {
  local p
  for _ in $(seq 1 200); do
    p=$((20000 + RANDOM % 30000))
    [ "$p" = "${1:-}" ] && continue
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then
      echo "$p"
      return
    fi
  done
  die 1 "no free TCP port found between 20000 and 50000"
}

write_config() {
  local dir=$1 node ctld_port slurmd_port
  # slurmd -C describes this machine as slurm.conf needs it (CPUs, sockets, cores, threads, memory); a
  # node line that claims more than the machine has would be drained at registration.
  node=$("$(program slurmd)" -C | head -n1)
  [[ "$node" == NodeName=* ]] || die 1 "slurmd -C printed no node line: $node"
  ctld_port=$(free_port)
  slurmd_port=$(free_port "$ctld_port")
  local name=${node%% *}
  name=${name#NodeName=}
  cat >"$dir/slurm.conf" <<EOF
# Written by tools/slurm/cluster.sh: a single-node cluster for tests, everything under $dir.
ClusterName=shadowbench
SlurmctldHost=$name(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/affinity
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1,batch_sched_delay=0,sched_min_interval=0
MinJobAge=3600
KillWait=2
InactiveLimit=0
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.txt
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=debug Nodes=$name Default=YES MaxTime=INFINITE State=UP
EOF
}

# Waits up to $1 seconds for the command after it to succeed.
wait_for() {
  local seconds=$1
  shift
  for _ in $(seq 1 $((seconds * 5))); do
    "$@" >/dev/null 2>&1 && return 0
    sleep 0.2
  done
  return 1
}

jobs_ended() {
  [ -z "$(squeue -h -t RUNNING,COMPLETING,SUSPENDED -o %A 2>/dev/null)" ]
}

node_idle() {
  [ "$(sinfo -h -N -o %T 2>/dev/null | head -n1)" = idle ]
}

start() {
  local dir=$1 owner=${2:-}
  require_machine
  mkdir -p "$dir"
  dir=$(cd "$dir" && pwd)
  [ ! -e "$dir/slurmctld.pid" ] || ! kill -0 "$(cat "$dir/slurmctld.pid")" 2>/dev/null ||
    die 2 "a cluster already runs in $dir (stop it with: bash tools/slurm/cluster.sh stop $dir)"
  # munged refuses a key, socket or log folder others may write to.
  chmod 700 "$dir"
  mkdir -p "$dir/state" "$dir/spool"
  if [ ! -s "$dir/munge.key" ]; then
    dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
    chmod 400 "$dir/munge.key"
  fi
  env "$kMarker=$dir" "$(program munged)" --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" \
    </dev/null >>"$dir/munged.log" 2>&1 || die 1 "munged did not start: see $dir/munged.log"
  wait_for 10 test -S "$dir/munge.socket" || die 1 "munged made no socket: see $dir/munged.log"
  write_config "$dir"
  export SLURM_CONF=$dir/slurm.conf
  env "$kMarker=$dir" "$(program slurmctld)" -f "$SLURM_CONF" </dev/null >>"$dir/slurmctld.log" 2>&1 ||
    die 1 "slurmctld did not start: see $dir/slurmctld.log"
  wait_for 20 scontrol ping || die 1 "slurmctld does not answer: see $dir/slurmctld.log"
  env "$kMarker=$dir" "$(program slurmd)" -f "$SLURM_CONF" </dev/null >>"$dir/slurmd.log" 2>&1 ||
    die 1 "slurmd did not start: see $dir/slurmd.log"
  if ! wait_for 30 node_idle; then
    die 1 "the node is not idle ($(sinfo -h -N -o '%T %E' 2>&1 | head -n1)): see $dir/slurmd.log and $dir/slurmctld.log"
  fi
  echo "export SLURM_CONF=$SLURM_CONF" >"$dir/env"
  if [ -n "$owner" ]; then
    # A watcher in its own session with its own files: it must not hold the caller's output open.
    setsid bash "${BASH_SOURCE[0]}" watch "$dir" "$owner" </dev/null >>"$dir/watch.log" 2>&1 &
    echo $! >"$dir/watch.pid"
  fi
  echo "tools/slurm/cluster.sh: cluster up in $dir ($(sinfo -h -N -o '%N %c CPUs %m MB')); SLURM_CONF=$SLURM_CONF"
}

# The processes started for the cluster in $1: those whose environment carries the marker with that
# value (the daemons and the slurmstepd processes slurmd forks), read from /proc.
cluster_processes() {
  local want="$kMarker=$1" p
  for p in /proc/[0-9]*; do
    [ "${p#/proc/}" = "$$" ] && continue
    { tr '\0' '\n' <"$p/environ"; } 2>/dev/null | grep -qxF "$want" && echo "${p#/proc/}"
  done
  return 0
}

stop() {
  local dir
  dir=$(cd "$1" 2>/dev/null && pwd) || die 2 "no cluster folder $1"
  export SLURM_CONF=$dir/slurm.conf
  # Jobs first, while slurmctld and slurmd can still end them (a killed slurmd orphans their processes).
  if [ -f "$SLURM_CONF" ] && scontrol ping >/dev/null 2>&1; then
    local jobs=()
    mapfile -t jobs < <(squeue -h -o %A 2>/dev/null | sort -u)
    [ ${#jobs[@]} -eq 0 ] || scancel "${jobs[@]}" 2>/dev/null || true
    wait_for 20 jobs_ended || true
  fi
  local pids=()
  mapfile -t pids < <(cluster_processes "$dir")
  if [ ${#pids[@]} -gt 0 ]; then
    kill -TERM "${pids[@]}" 2>/dev/null || true
    for _ in $(seq 1 50); do
      mapfile -t pids < <(cluster_processes "$dir")
      [ ${#pids[@]} -eq 0 ] && break
      sleep 0.2
    done
    [ ${#pids[@]} -eq 0 ] || kill -KILL "${pids[@]}" 2>/dev/null || true
  fi
  if [ -f "$dir/watch.pid" ] && [ "$(cat "$dir/watch.pid")" != "${SHADOWBENCH_SLURM_WATCHER:-}" ]; then
    kill "$(cat "$dir/watch.pid")" 2>/dev/null || true
  fi
  rm -f "$dir/watch.pid" "$dir/slurmctld.pid" "$dir/slurmd.pid" "$dir/munged.pid"
  echo "tools/slurm/cluster.sh: cluster in $dir stopped"
}

watch() {
  local dir=$1 owner=$2
  export SHADOWBENCH_SLURM_WATCHER=$$
  while kill -0 "$owner" 2>/dev/null; do sleep 1; done
  stop "$dir"
}

case "${1:-}" in
  start)
    [ $# -eq 2 ] || { [ $# -eq 4 ] && [ "$3" = --owner ]; } || die 2 "usage: start DIR [--owner PID]"
    start "$2" "${4:-}"
    ;;
  stop)
    [ $# -eq 2 ] || die 2 "usage: stop DIR"
    stop "$2"
    ;;
  watch)
    [ $# -eq 3 ] || die 2 "usage: watch DIR PID (started by start --owner)"
    watch "$2" "$3"
    ;;
  run)
    if [ $# -lt 4 ] || [ "$3" != -- ]; then die 2 "usage: run DIR -- COMMAND..."; fi
    dir=$2
    shift 3
    start "$dir" "$$"
    trap 'stop "$dir"' EXIT
    rc=0
    SLURM_CONF=$(cd "$dir" && pwd)/slurm.conf "$@" || rc=$?
    exit "$rc"
    ;;
  *)
    die 2 "usage: start DIR [--owner PID] | stop DIR | run DIR -- COMMAND... (see the header of this file)"
    ;;
esac
