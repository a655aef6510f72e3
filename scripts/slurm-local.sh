#!/usr/bin/env bash
# A single-node Slurm on this machine, to run a sweep as the job array that
# `rattleback sweep --emit slurm` writes, exactly as on a cluster: munged with a fresh key,
# slurmctld and slurmd on this host (SlurmUser=root, proctrack/linuxproc, task/none), state and
# spool under a temporary folder, one node with this machine's CPUs in one partition. It submits
# the job script, waits for the array and its merge, checks that the merged table equals the
# in-process one (all columns but wall_s), and stops only the daemons it started (pid files).
#
# Usage (as root; Debian packages slurm-wlm and munge):
#   scripts/slurm-local.sh [RATTLEBACK [SWEEP.yaml [SHARDS]]]
# Exit: 0 equal, 1 different or failed, 77 skipped (not root, or Slurm/munge missing).
set -euo pipefail
cd "$(dirname "$0")/.."
rb=$(realpath "${1:-build/app/rattleback}")
sweep_file=${2:-}
shards=${3:-3}

if [ "$(id -u)" -ne 0 ]; then echo "slurm-local: skipped: needs root (SlurmUser=root)"; exit 77; fi
for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "slurm-local: skipped: $tool missing (apt-get install slurm-wlm munge)"; exit 77
  fi
done

work=$(mktemp -d /tmp/rattleback-slurm-XXXXXX)
started=()
stop_daemons() {
  for pidfile in "${started[@]}"; do
    [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
  done
  sleep 0.5
  for pidfile in "${started[@]}"; do
    [ -f "$pidfile" ] && kill -9 "$(cat "$pidfile")" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap stop_daemons EXIT

# A sweep of its own unless one is given: 12 short runs.
if [ -z "$sweep_file" ]; then
  sweep_file=$work/sweep.yaml
  cat > "$sweep_file" <<EOF
base: $(pwd)/scenes/rattleback.yaml
vary:
  initial.spin: {from: -6, to: 6, count: 4}
  contact.air_drag: [0.0, 5.9e-6, 5.9e-5]
duration: 3.0
EOF
fi
sweep_file=$(realpath "$sweep_file")

# munge: a key of its own, its own socket.
mkdir -p "$work/munge"
chmod 700 "$work/munge"
mungekey --create --keyfile="$work/munge/munge.key" >/dev/null 2>&1 || mungekey -c -k "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/munge.socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" \
  --seed-file="$work/munge/munged.seed"
started+=("$work/munge/munged.pid")

host=$(hostname -s)
cpus=$(nproc)
memory=$(awk '/MemTotal/ {print int($2 / 1024 * 0.9)}' /proc/meminfo)
# Free ports for the two daemons.
ports=$(python3 -c 'import socket
s=[socket.socket() for _ in range(2)]
[x.bind(("127.0.0.1",0)) for x in s]
print(" ".join(str(x.getsockname()[1]) for x in s))')
read -r ctld_port slurmd_port <<<"$ports"
mkdir -p "$work/state" "$work/spool" "$work/log"
cat > "$work/slurm.conf" <<EOF
ClusterName=rattleback-local
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$work/slurm.conf
slurmctld -c -f "$SLURM_CONF"
started+=("$work/slurmctld.pid")
slurmd -c -f "$SLURM_CONF"
started+=("$work/slurmd.pid")

# Wait for the node to come up idle.
for _ in $(seq 1 60); do
  state=$(sinfo -h -o '%t' 2>/dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
if [ "$state" != idle ]; then
  echo "slurm-local: the node did not come up (state '$state'); logs in $work/log:" >&2
  tail -5 "$work/log/"*.log >&2 || true
  exit 1
fi
echo "slurm-local: slurmctld and slurmd up on $host ($cpus CPUs) in $work"

# Into a folder that does not exist yet: the script's #SBATCH --output points into it, and
# Slurm opens that before the script's first line runs (the tasks failed with nothing said).
out=$work/fresh/out/table.csv
"$rb" sweep "$sweep_file" --emit slurm --shards "$shards" -o "$out" > "$work/job.sh"
job=$(sbatch --parsable "$work/job.sh")
echo "slurm-local: submitted job array $job ($shards tasks) and, from its first task, the merge"

# Wait for the array, then for the merge it submits, to leave the queue.
# An empty queue for 5 s with no table means the jobs failed (e.g. their logs could not be
# opened): say so then, with the logs, rather than after the timeout.
deadline=$((SECONDS + 300))
empty=0
while :; do
  queue=$(squeue -h -o %i 2>/dev/null || true)
  [ -f "$out" ] && [ -z "$queue" ] && break
  if [ -z "$queue" ]; then empty=$((empty + 1)); else empty=0; fi
  if [ $SECONDS -gt $deadline ] || [ $empty -gt 10 ]; then
    echo "slurm-local: no merged table $out; queue:" >&2
    squeue >&2 || true
    cat "$(dirname "$out")"/slurm-*.out >&2 2>/dev/null || true
    grep -i "could not\|error" "$work/log/slurmd.log" >&2 || true
    exit 1
  fi
  sleep 0.5
done

"$rb" sweep "$sweep_file" -q -o "$work/in-process.csv"
strip() { sed 's/,[^,]*$//' "$1"; }
if diff <(strip "$out") <(strip "$work/in-process.csv") >/dev/null; then
  echo "slurm-local: the merged table of the job array equals the in-process one ($(($(wc -l < "$out") - 1)) rows)"
  exit 0
fi
echo "slurm-local: the merged table differs from the in-process one:" >&2
diff <(strip "$out") <(strip "$work/in-process.csv") >&2 || true
exit 1
