#!/usr/bin/env bash
# `illum render --shard` under a real Slurm: a private single-node cluster (munged, slurmctld and
# slurmd from Debian's slurm-wlm, started here in a scratch folder with a configuration of their
# own, and stopped by their own PIDs) runs a 3-task job array over assimp's test models; the union
# of the tasks' pictures must equal, byte for byte, one unsharded run.
#   tests/slurm/shard_array_test.sh ILLUM_BINARY
# Exit 0: passed; 77: Slurm is not installed (skipped); anything else: failed.
set -euo pipefail
illum=$(realpath "$1")
for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool is not installed (apt-get install slurmctld slurmd slurm-client munge)"; exit 77; }
done
work=$(mktemp -d /tmp/illum_slurm.XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  sleep 0.5
  for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAILED: $*"; for log in "$work"/*.log; do echo "--- $log"; tail -20 "$log"; done; exit 1; }

# munge: a key of our own and a socket in a folder everyone may enter.
mkdir -p "$work/munge"
chmod 711 "$work/munge"
mungekey --create --keyfile "$work/munge/munge.key" --force 2>/dev/null || dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 2>/dev/null
chmod 600 "$work/munge/munge.key"
munged --force --key-file "$work/munge/munge.key" --socket "$work/munge/munge.socket" \
  --pid-file "$work/munge/munged.pid" --log-file "$work/munge.log" --seed-file "$work/munge/seed"
for _ in $(seq 50); do [ -s "$work/munge/munged.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$work/munge/munged.pid")")

# Free ports for the two daemons.
port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" <<CONF
ClusterName=illumtest
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$(port)
SlurmdPort=$(port)
AuthType=auth/munge
AuthInfo=socket=$work/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
NodeName=illumnode NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=batch Nodes=illumnode Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -i > "$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N illumnode > "$work/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do sinfo -h -o %T 2>/dev/null | grep -q idle && break; sleep 0.1; done
sinfo -h -o %T | grep -q idle || fail "the node did not come up"

models=/usr/share/assimp/models
inputs=("'$models/PLY/*.ply'" "'$models/STL/*.stl'" "$models/glTF2/BoxTextured-glTF-Binary")
common="--resolution 96,72 --samples 1 --threads 1 -q -o {ext}/{stem}.png"
# The whole batch in one run, for comparison (some test models are refused in both).
eval "$illum" render "${inputs[@]}" $common --output-dir "$work/whole" 2> "$work/whole.err" || true
sbatch --array=0-2 --output="$work/task_%a.out" --chdir="$work" --cpus-per-task=1 \
  --wrap "$illum render ${inputs[*]} $common --shard \$SLURM_ARRAY_TASK_ID/3 --output-dir $work/sharded || true" > "$work/sbatch.out" ||
  fail "sbatch refused the job array"
for _ in $(seq 600); do [ -z "$(squeue -h 2>/dev/null)" ] && break; sleep 0.2; done
[ -z "$(squeue -h)" ] || fail "the job array did not finish"
[ -d "$work/sharded" ] || fail "no task wrote a picture"
whole=$(cd "$work/whole" && find . -type f | sort)
sharded=$(cd "$work/sharded" && find . -type f | sort)
[ "$whole" = "$sharded" ] || fail "the tasks wrote $(echo "$sharded" | wc -l) pictures, the whole run $(echo "$whole" | wc -l)"
for f in $whole; do cmp -s "$work/whole/$f" "$work/sharded/$f" || fail "$f differs"; done
tasks=$(ls "$work"/task_*.out | wc -l)
[ "$tasks" -eq 3 ] || fail "expected 3 array tasks, found $tasks"
echo "passed: 3 Slurm array tasks wrote the $(echo "$whole" | wc -l) pictures of the whole run, byte for byte"
