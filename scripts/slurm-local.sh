#!/usr/bin/env bash
# A single-node Slurm cluster on localhost for tests (Debian's slurm-wlm and munge), entirely
# under one work folder: its own munge key, socket and daemon, slurm.conf, state and logs.
#   scripts/slurm-local.sh start WORK   # prints "export SLURM_CONF=WORK/slurm.conf"; waits until the node is idle
#   scripts/slurm-local.sh stop WORK    # stops the daemons it started (by their pid files)
# Exit 77 when slurm or munge is not installed or cannot start (tests treat it as skipped).
set -euo pipefail
action=${1:?start|stop} work=$(realpath -m "${2:?work folder}")
for tool in munged slurmctld slurmd sbatch sinfo; do
  command -v "$tool" > /dev/null || { echo "slurm-local: $tool not installed" >&2; exit 77; }
done
conf=$work/slurm.conf

stop() {
  for pidfile in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munged.pid"; do
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2> /dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
    rm -f "$pidfile"
  done
}

if [ "$action" = stop ]; then stop; exit 0; fi
[ "$action" = start ] || { echo "usage: $0 start|stop WORK" >&2; exit 2; }

stop
mkdir -p "$work/state" "$work/spool" "$work/munge"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
socket=$work/munge/munge.socket
munged --force --socket="$socket" --key-file="$work/munge/munge.key" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munge/seed" || { echo "slurm-local: munged failed" >&2; exit 77; }

host=$(hostname -s)
cpus=$(nproc)
# Two ports the kernel says are free now, so a second cluster or another service on the host does not collide.
read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in socks))')
user=$(id -un)
cat > "$conf" <<CONF
ClusterName=proxygi-local
SlurmctldHost=$host(127.0.0.1)
SlurmUser=$user
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$conf
slurmctld -f "$conf" || { echo "slurm-local: slurmctld failed (see $work/slurmctld.log)" >&2; stop; exit 77; }
slurmd -f "$conf" || { echo "slurm-local: slurmd failed (see $work/slurmd.log)" >&2; stop; exit 77; }
for _ in $(seq 100); do
  if sinfo -h -o '%t' 2> /dev/null | grep -qE '^idle'; then echo "export SLURM_CONF=$conf"; exit 0; fi
  sleep 0.2
done
echo "slurm-local: the node did not become idle; sinfo says: $(sinfo -h 2>&1)" >&2
stop
exit 77
