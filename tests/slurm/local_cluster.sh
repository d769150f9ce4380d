# A Slurm cluster of one node on this machine, in a folder of its own, for tests and measurements
# (tests/slurm/slurm_cluster_test.sh, scripts/slurm_scaling.sh): Debian's munged, slurmctld and
# slurmd, with their own munge key and socket, a generated slurm.conf (the current user as
# SlurmUser and SlurmdUser, proctrack/linuxproc and task/none: no cgroups or systemd needed; one
# node of this machine's CPUs and memory; free ports; batch jobs scheduled as soon as CPUs free
# up, not after the default 3 s batch_sched_delay, which made an 8-task array and its merge take
# 15 s rather than 6) and every file under DIR. Source it, then:
#   start_local_cluster DIR   starts the three daemons and waits until the node is idle; exports
#                             SLURM_CONF for sbatch, squeue, scancel, scontrol and sinfo
#   stop_local_cluster DIR    cancels every job and stops the daemons (for a trap: never fails)
# slurmd must run as root to start jobs.

# A port nothing listens on (bash connects to it; a refused connection means free).
local_cluster_free_port() {
  local port
  while :; do
    port=$((20000 + RANDOM % 40000))
    (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null || { echo "$port"; return; }
  done
}

start_local_cluster() {
  local dir=$1 node ctld_port slurmd_port memory_mb
  chmod 755 "$dir"  # munged wants its socket's folder searchable by all
  mungekey --create --keyfile="$dir/munge.key" || return 1
  munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" --pid-file="$dir/munged.pid" \
    --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" || return 1
  node=$(hostname -s)
  ctld_port=$(local_cluster_free_port)
  slurmd_port=$(local_cluster_free_port)
  [ "$ctld_port" != "$slurmd_port" ] || slurmd_port=$(local_cluster_free_port)
  memory_mb=$(awk '/MemTotal/ { print int($2 / 1024) - 256 }' /proc/meminfo)
  mkdir -p "$dir/state" "$dir/spool"
  cat >"$dir/slurm.conf" <<CONF
ClusterName=prismlocal
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SchedulerType=sched/builtin
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SlurmdParameters=config_overrides
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory_mb State=UNKNOWN
PartitionName=prism Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -i -f "$SLURM_CONF" || return 1
  slurmd -f "$SLURM_CONF" || return 1
  for _ in $(seq 100); do
    [ "$(sinfo -h -o %t 2>/dev/null)" = idle ] && return 0
    sleep 0.2
  done
  echo "the node did not become idle: $(sinfo -h -o '%t %E' 2>&1)" >&2
  return 1
}

stop_local_cluster() {
  local dir=$1 daemon
  if [ -f "$dir/slurmctld.pid" ]; then
    scancel --full --quiet --user="$(id -un)" 2>/dev/null || true
    for _ in $(seq 50); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.2; done
  fi
  for daemon in slurmd slurmctld munged; do
    [ -f "$dir/$daemon.pid" ] && kill "$(cat "$dir/$daemon.pid")" 2>/dev/null
  done
  for daemon in slurmd slurmctld munged; do
    for _ in $(seq 50); do
      [ -f "$dir/$daemon.pid" ] && kill -0 "$(cat "$dir/$daemon.pid")" 2>/dev/null || break
      sleep 0.1
    done
  done
  return 0
}
