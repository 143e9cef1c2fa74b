#!/usr/bin/env bash
# `wifislam paper` through Slurm on a one-node cluster of this script's own (munged, slurmctld and
# slurmd in a scratch folder, on ports of its own, found through SLURM_CONF: nothing of the
# machine's is read or changed): `paper --slurm TASKS --submit` writes the job array (task i runs
# `paper --shard i/TASKS`) and the report job, submits both, and this waits for the report. It
# stops exactly the daemons it started, also on failure or Ctrl-C.
#
#   bench/paper/slurm_one_node.sh [build-dir] [paper-folder] [seeds] [tasks] [cpus-per-task]
#   (defaults: build/release, a temp dir, 5, 2, 1; a 2-core node runs 2 one-CPU tasks at a time)
set -euo pipefail
build=$(cd "${1:-build/release}" && pwd)
out=${2:-$(mktemp -d)/paper}
seeds=${3:-5}
tasks=${4:-2}
cpus=${5:-1}
bin="$build/apps/wifislam"
for p in munged slurmctld slurmd sbatch sinfo; do
  command -v "$p" >/dev/null || [ -x "/usr/sbin/$p" ] || {
    echo "$p not found: scripts/install-deps.sh installs slurm-wlm and munge" >&2; exit 1; }
done
PATH=/usr/sbin:$PATH
scratch=$(mktemp -d /tmp/wifislam_slurm.XXXXXX)
mkdir -p "$scratch"/{munge,state,spool,log}
chmod 700 "$scratch/munge"
head -c 1024 /dev/urandom >"$scratch/munge/munge.key"
chmod 600 "$scratch/munge/munge.key"
host=$(hostname -s)
port=$((21000 + 2 * ($$ % 5000)))
export SLURM_CONF="$scratch/slurm.conf"
cat >"$SLURM_CONF" <<CONF
ClusterName=wifislampaper
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$scratch/munge/munge.socket
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$scratch/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/log/slurmctld.log
SlurmdLogFile=$scratch/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host CPUs=$(nproc) RealMemory=8000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
pids=()
stop() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
}
trap stop EXIT
munged --foreground --force --socket="$scratch/munge/munge.socket" \
  --key-file="$scratch/munge/munge.key" --log-file="$scratch/log/munged.log" \
  --pid-file="$scratch/munge/munged.pid" --seed-file="$scratch/munge/munged.seed" \
  >"$scratch/log/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -S "$scratch/munge/munge.socket" ] && break; sleep 0.05; done
slurmctld -D >"$scratch/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D >"$scratch/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 240); do sinfo -h -o %T 2>/dev/null | grep -q idle && break; sleep 0.25; done
sinfo -h -o %T | grep -q idle || { echo "the node never became idle" >&2; exit 1; }

start=$(date +%s)
"$bin" paper -o "$out" --seeds "$seeds" --slurm "$tasks" --cpus-per-task "$cpus" --submit
until [ -f "$out/report.md" ] && ! squeue -h | grep -q .; do
  # A failed task leaves the report job waiting for ever.
  if squeue -h -o %r 2>/dev/null | grep -q DependencyNeverSatisfied; then break; fi
  sleep 10
done
echo "Slurm, $tasks tasks x $cpus CPU, $seeds seed(s): $(( $(date +%s) - start )) s wall"
sacct -X -o JobID,JobName%20,State,Elapsed 2>/dev/null || true
[ -f "$out/report.md" ] || { echo "no report: see $out/slurm/logs" >&2; exit 1; }
echo "report: $out/report.md"
