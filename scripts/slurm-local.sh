#!/usr/bin/env bash
# A real single-node Slurm on this machine, to try a campaign's sbatch recipe
# (docs/campaigns.md) without a cluster: Debian's slurm-wlm and munge, installed if missing,
# a slurm.conf for localhost in a state folder, and munged, slurmctld and slurmd started by
# hand (no systemd). Needs root (or sudo).
#
#   scripts/slurm-local.sh start   install what is missing, configure, start the daemons and
#                                  wait for the node to be idle; then in your shell:
#                                  export SLURM_CONF=/tmp/vsr-slurm/slurm.conf
#   scripts/slurm-local.sh stop    stop the daemons it started (by their pid files)
#
# VSR_SLURM_STATE overrides the state folder (default /tmp/vsr-slurm): config, logs, spool.
set -euo pipefail

state=${VSR_SLURM_STATE:-/tmp/vsr-slurm}
export SLURM_CONF=$state/slurm.conf
munge_pid=$state/munged.pid

say() { printf 'slurm-local: %s\n' "$*"; }
fail() { printf 'slurm-local: %s\n' "$*" >&2; exit 1; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else fail "'$*' needs root"
  fi
}

install() {
  if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
    say "installing Debian slurm-wlm and munge"
    as_root apt-get update -q
    DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -q --no-install-recommends slurm-wlm munge
  fi
}

# A free TCP port from $1 up (nothing listening), so that two local Slurms (two test runs
# at once) do not meet.
free_port() {
  local port=$1
  while ss -Hltn "sport = :$port" | grep -q .; do port=$((port + 1)); done
  echo "$port"
}

# One node, this host, with its CPUs as slurmd detects them and half its memory (so that
# `--mem` requests fit), one partition; no accounting, no cgroups.
write_conf() {
  local host node memory ctld_port slurmd_port
  ctld_port=$(free_port $((20000 + RANDOM % 20000)))
  slurmd_port=$(free_port $((ctld_port + 1)))
  host=$(hostname -s)
  node=$(slurmd -C | head -1 | sed 's/ RealMemory=[0-9]*//')
  memory=$(( $(free -m | awk '/^Mem:/ { print $2 }') / 2 ))
  mkdir -p "$state/ctld" "$state/spool"
  cat > "$SLURM_CONF" <<EOF
ClusterName=vsr-local
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
AuthType=auth/munge
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/slurmctld.log
SlurmdLogFile=$state/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
$node NodeAddr=127.0.0.1 RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
}

# munged runs as the munge user; its pid is copied into the state folder only when this
# script started it, so `stop` never stops a munged it did not start.
start_munge() {
  if [ -S /run/munge/munge.socket.2 ] && munge -n >/dev/null 2>&1; then return; fi
  [ -f /etc/munge/munge.key ] || as_root /usr/sbin/mungekey --create
  as_root mkdir -p /run/munge
  as_root chown munge:munge /run/munge
  as_root runuser -u munge -- /usr/sbin/munged --pid-file=/run/munge/munged.pid
  cp /run/munge/munged.pid "$munge_pid"
}

start() {
  install
  [ -f "$state/slurmctld.pid" ] && fail "already started ($state); run '$0 stop' first"
  mkdir -p "$state"
  write_conf
  start_munge
  as_root slurmctld -c
  as_root slurmd
  for _ in $(seq 60); do
    case $(sinfo -h -o %T 2>/dev/null) in
      idle) say "up: export SLURM_CONF=$SLURM_CONF"; return ;;
    esac
    sleep 1
  done
  fail "the node did not come up in 60 s; see $state/slurmctld.log and $state/slurmd.log"
}

# Stops only the daemons this script started, by the pid files in its state folder.
stop() {
  local file pid
  for file in slurmd.pid slurmctld.pid munged.pid; do
    [ -f "$state/$file" ] || continue
    pid=$(cat "$state/$file")
    if kill -0 "$pid" 2>/dev/null; then as_root kill "$pid"; fi
    for _ in $(seq 30); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
    as_root rm -f "$state/$file"
  done
  say "stopped"
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  *) echo "usage: $0 start|stop" >&2; exit 2 ;;
esac
