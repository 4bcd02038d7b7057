#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, for `texsim regress --slurm` and its test
# (docs/regress.md): Debian's slurm-wlm and munge, configured for this host, its daemons started
# or stopped. Needs root (the daemons' users and /etc).
#
#   scripts/slurm_local.sh start    configure, start munged, slurmctld and slurmd; wait until the
#                                   node is idle; print the partition
#   scripts/slurm_local.sh stop     stop the daemons this script started
#   scripts/slurm_local.sh status   sinfo
#
# The configuration goes to $TMU_SLURM_DIR (default /tmp/tmu_slurm): slurm.conf with the host as
# controller and only node (its cores and memory), a partition `tmu`, process tracking without
# cgroups (proctrack/linuxproc, task/none: a container has no cgroup delegation), state and
# spool folders, and the daemons' pid files, so `stop` stops exactly what `start` started; ports
# 6917 and 6918 (not Slurm's 6817, 6818), so a Slurm already on the machine is left alone. An
# existing /etc/slurm/slurm.conf is not touched: the daemons and clients read ours through
# SLURM_CONF (export SLURM_CONF=$TMU_SLURM_DIR/slurm.conf to use sinfo, squeue, sbatch).
set -euo pipefail
dir=${TMU_SLURM_DIR:-/tmp/tmu_slurm}
export SLURM_CONF=$dir/slurm.conf
host=$(hostname -s)

die() { echo "slurm_local: $*" >&2; exit 1; }

configure() {
  mkdir -p "$dir/state" "$dir/spool" "$dir/log"
  chown -R slurm:slurm "$dir/state" "$dir/log" 2>/dev/null || true
  local cpus mem
  cpus=$(nproc)
  mem=$(awk '/MemTotal/ { print int($2 / 1024 * 0.9) }' /proc/meminfo)
  cat >"$SLURM_CONF" <<CONF
ClusterName=tmu
SlurmctldHost=$host
SlurmctldPort=${TMU_SLURMCTLD_PORT:-6917}
SlurmdPort=${TMU_SLURMD_PORT:-6918}
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SchedulerType=sched/backfill
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=tmu Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

start() {
  command -v slurmctld >/dev/null || die "slurm-wlm is not installed (scripts/setup.sh installs it)"
  command -v munged >/dev/null || die "munge is not installed (scripts/setup.sh installs it)"
  configure
  if ! pgrep -x munged >/dev/null; then
    [[ -s /etc/munge/munge.key ]] || { mungekey --create 2>/dev/null || /usr/sbin/create-munge-key -f; }
    mkdir -p /run/munge && chown munge:munge /run/munge
    runuser -u munge -- /usr/sbin/munged
    touch "$dir/started_munged"
  fi
  /usr/sbin/slurmctld
  /usr/sbin/slurmd
  for _ in $(seq 1 60); do
    if sinfo -h -o '%t' 2>/dev/null | grep -qx 'idle'; then
      sinfo
      return 0
    fi
    sleep 0.5
  done
  sinfo || true
  tail -5 "$dir/log/slurmctld.log" "$dir/log/slurmd.log" >&2 || true
  die "the node did not come up idle within 30 s (logs in $dir/log)"
}

stop() {
  for pidfile in "$dir/slurmd.pid" "$dir/slurmctld.pid"; do
    if [[ -s $pidfile ]]; then
      kill "$(cat "$pidfile")" 2>/dev/null || true
      rm -f "$pidfile"
    fi
  done
  if [[ -e $dir/started_munged ]]; then
    pkill -x munged 2>/dev/null || true
    rm -f "$dir/started_munged"
  fi
  # Wait until they are gone, so a test leaves nothing behind.
  for _ in $(seq 1 40); do
    pgrep -x slurmctld >/dev/null || pgrep -x slurmd >/dev/null || return 0
    sleep 0.25
  done
  die "slurmctld or slurmd still running"
}

case ${1:-} in
  start) start ;;
  stop) stop ;;
  status) sinfo ;;
  *) sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
