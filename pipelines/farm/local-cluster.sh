#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for tests and for trying the farm
# scripts without a real cluster (docs/farm.md).
#
#   local-cluster.sh start [DIR]   write DIR/slurm.conf, start munged, slurmctld
#                                  and slurmd as root, wait until the node is idle
#   local-cluster.sh stop  [DIR]   stop those daemons (by their pid files)
#
# DIR (default: $DEWPOINT_SLURM_DIR or /tmp/dewpoint-slurm) holds the
# configuration, state, logs and pid files. Clients need SLURM_CONF=DIR/slurm.conf;
# `start` prints that line. It needs neither systemd nor cgroups: processes are
# tracked through /proc and tasks are not confined, so it runs inside a container.
set -euo pipefail

die() { echo "local-cluster: $*" >&2; exit 1; }

action=${1:-}
dir=${2:-${DEWPOINT_SLURM_DIR:-/tmp/dewpoint-slurm}}
ctld_port=${DEWPOINT_SLURMCTLD_PORT:-6817}
slurmd_port=${DEWPOINT_SLURMD_PORT:-6818}

# Slurm's daemons run jobs as any user and so need root; munged's key too.
require_tools() {
  [ "$(id -u)" -eq 0 ] || die "must run as root (slurmd starts jobs on behalf of users)"
  local t
  for t in munged slurmctld slurmd sinfo scontrol; do
    command -v "$t" >/dev/null || die "$t not found; install slurm-wlm and munge (pipelines/install-deps.sh)"
  done
}

write_munge_key() {
  mkdir -p "$dir/munge"
  chmod 700 "$dir/munge"
  head -c 1024 /dev/urandom >"$dir/munge/munge.key"
  chmod 400 "$dir/munge/munge.key"
}

start_munged() {
  # --force: the key and socket live in a temporary folder whose parents
  # munged would otherwise refuse as not owned or too open.
  munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
    --seed-file="$dir/munge/munged.seed" || die "munged did not start; see $dir/munge/munged.log"
}

write_slurm_conf() {
  local host cpus
  host=$(hostname -s)
  cpus=$(nproc)
  mkdir -p "$dir/state" "$dir/spool" "$dir/log"
  cat >"$dir/slurm.conf" <<CONF
# Written by pipelines/farm/local-cluster.sh: one node, this machine.
ClusterName=dewpoint-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool/slurmd-%n
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
# No systemd, no cgroups: track processes through /proc, do not bind tasks.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# Jobs whose dependency can never be met are cancelled, not left pending.
SchedulerParameters=kill_invalid_depend
# Finished jobs stay visible to scontrol for ten minutes.
MinJobAge=600
ReturnToService=2
SlurmdParameters=config_overrides
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

wait_for_idle_node() {
  local state
  for _ in $(seq 1 60); do
    state=$(SLURM_CONF="$dir/slurm.conf" sinfo -h -N -o '%T' 2>/dev/null | head -n1 || true)
    case "$state" in
      idle) return 0 ;;
      down* | drain* | fail*) SLURM_CONF="$dir/slurm.conf" scontrol update nodename="$(hostname -s)" state=resume 2>/dev/null || true ;;
    esac
    sleep 1
  done
  die "node not idle after 60 s (state '${state:-none}'); see $dir/log/"
}

start() {
  require_tools
  if [ -f "$dir/slurmctld.pid" ] && running "$(cat "$dir/slurmctld.pid")"; then
    die "a cluster already runs from $dir (stop it first)"
  fi
  mkdir -p "$dir"
  write_munge_key
  start_munged
  write_slurm_conf
  export SLURM_CONF="$dir/slurm.conf"
  # -i: ignore state a previous cluster in the same folder left behind.
  slurmctld -i || die "slurmctld did not start; see $dir/log/slurmctld.log"
  slurmd || die "slurmd did not start; see $dir/log/slurmd.log"
  wait_for_idle_node
  echo "SLURM_CONF=$dir/slurm.conf"
}

# A daemon that has exited but was not reaped (a container whose first
# process does not reap orphans) still answers kill -0; it counts as gone.
running() {
  local state
  state=$(cut -d' ' -f3 "/proc/$1/stat" 2>/dev/null) && [ -n "$state" ] && [ "$state" != Z ]
}

stop_daemon() {
  local pidfile=$1 pid
  [ -f "$pidfile" ] || return 0
  pid=$(cat "$pidfile")
  if running "$pid"; then
    kill "$pid"
    for _ in $(seq 1 50); do running "$pid" || break; sleep 0.1; done
    if running "$pid"; then kill -9 "$pid" 2>/dev/null || true; fi
  fi
  rm -f "$pidfile"
}

stop() {
  [ -d "$dir" ] || return 0
  stop_daemon "$dir/slurmd.pid"
  stop_daemon "$dir/slurmctld.pid"
  stop_daemon "$dir/munge/munged.pid"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  *) echo "usage: local-cluster.sh start|stop [DIR]" >&2; exit 2 ;;
esac
