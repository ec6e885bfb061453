# A one-node Slurm cluster of the test's own, on 127.0.0.1 (sourced by the `slurm` tests):
# slurmctld and slurmd as the test's processes, with no munge (AuthType=auth/none), no cgroups and
# no accounting database, their configuration, state and logs in one folder, stopped when the test
# exits. Slurm's commands find it through SLURM_CONF.
#   start_slurm_cluster DIR

stop_slurm_cluster() {
  local dir=$1 pid
  for daemon in slurmd slurmctld; do
    [ -f "$dir/$daemon.pid" ] || continue
    pid=$(cat "$dir/$daemon.pid")
    kill "$pid" 2> /dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
  done
}

start_slurm_cluster() {
  local dir=$1 user ports
  rm -rf "$dir"
  mkdir -p "$dir/state" "$dir/spool"
  user=$(id -un)
  ports=$(python3 -c '
import socket
held = [socket.socket() for _ in range(2)]
for s in held: s.bind(("127.0.0.1", 0))
print(" ".join(str(s.getsockname()[1]) for s in held))')
  read -r ctl_port node_port <<< "$ports"
  cat > "$dir/slurm.conf" << CONF
ClusterName=kestreltest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctl_port
SlurmdPort=$node_port
AuthType=auth/none
CredType=cred/none
SlurmUser=$user
SlurmdUser=$user
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
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
MinJobAge=600
NodeName=kestrel-node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=kestrel-node Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$dir/slurm.conf"
  trap "stop_slurm_cluster '$dir'" EXIT
  slurmctld -i -f "$SLURM_CONF"
  slurmd -f "$SLURM_CONF" -N kestrel-node
  for _ in $(seq 150); do
    [ "$(sinfo -h -o %T 2> /dev/null)" = idle ] && return 0
    sleep 0.2
  done
  echo "the test's Slurm cluster did not come up:" >&2
  tail -n 5 "$dir"/slurmctld.log "$dir"/slurmd.log >&2
  return 1
}
