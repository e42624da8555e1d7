#!/bin/sh
# A sweep through a real Slurm on this one machine: starts munged,
# slurmctld and slurmd (as root, with a private configuration, socket,
# ports and spool folders under a temporary folder), submits the sweep with
# --slurm, waits for the job array and the merge job, and checks that the
# merged runs.csv and failed.csv are byte-identical to a local sweep's.
# Needs root and the Debian packages slurm-wlm and munge.
#
#   tests/experiment/slurm_single_node.sh BUILD_DIR [SOURCE_DIR]
#
# Exit status: 0 passed, 1 failed, 77 cannot run here (not root, no Slurm).
set -u
build=$(cd "${1:?usage: slurm_single_node.sh BUILD_DIR [SOURCE_DIR]}" && pwd)
source_dir=$(cd "${2:-$(dirname "$0")/../..}" && pwd)
vv=$build/vvinterpreter/vvinterpreter
model=$source_dir/tests/experiment/models/sweep_model.vvp
cache=$build/test-model-cache

skip() { echo "slurm_single_node: skipped: $*"; exit 77; }
[ "$(id -u)" = 0 ] || skip "needs root to start slurmctld and slurmd"
for tool in munged slurmctld slurmd sbatch squeue sinfo; do
  command -v $tool > /dev/null || [ -x /usr/sbin/$tool ] || skip "$tool is not installed (Debian: slurm-wlm, munge)"
done
PATH=$PATH:/usr/sbin

work=$(mktemp -d /tmp/vv-slurm-XXXXXX)
pids=""
finish() {
  for p in $pids; do kill "$p" 2> /dev/null; done
  sleep 1
  for p in $pids; do kill -9 "$p" 2> /dev/null; done
  if [ "${keep:-0}" = 1 ]; then echo "slurm_single_node: left $work"; else rm -rf "$work"; fi
}
trap finish EXIT
fail() {
  echo "slurm_single_node: FAILED: $*"
  for log in "$work"/*.log "$work"/out/slurm/*.out; do [ -f "$log" ] && { echo "== $log"; tail -20 "$log"; }; done
  keep=1
  exit 1
}

# munge, private: its own key, socket, pid and log (a munged the system
# runs is left alone).
mkdir -p "$work/munge" "$work/spool/ctld" "$work/spool/d"
chmod 700 "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 2> /dev/null
chmod 400 "$work/munge/munge.key"
munged --force --key-file="$work/munge/munge.key" --socket="$work/munge/socket" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge.log" --seed-file="$work/munge/seed" ||
  fail "munged did not start"
pids="$pids $(cat "$work/munge/munged.pid")"

host=$(hostname -s)
cpus=$(nproc)
# Ports of its own: other checkouts may run this test at the same time.
free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])' 2> /dev/null ||
    echo $((20000 + $$ % 20000 + $1))
}
ctld_port=$(free_port 0)
d_port=$(free_port 1)
cat > "$work/slurm.conf" << CONF
ClusterName=vvtest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/spool/ctld
SlurmdSpoolDir=$work/spool/d
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=vvtest Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -D -f "$SLURM_CONF" > "$work/slurmctld.out.log" 2>&1 &
pids="$pids $!"
slurmd -D -f "$SLURM_CONF" > "$work/slurmd.out.log" 2>&1 &
pids="$pids $!"
up=0
for i in $(seq 1 60); do
  if sinfo -h -o %T 2> /dev/null | grep -q idle; then up=1; break; fi
  sleep 0.5
done
[ $up = 1 ] || fail "the node did not become idle in 30 s ($(sinfo -h -o '%T %E' 2>&1))"

# The same sweep, here and through Slurm (2 array tasks, then the merge).
"$vv" --cache "$cache" --quiet --sweep rate=0.5,3,2 --seeds 2 --steps 3 --out "$work/local" "$model" > /dev/null 2>&1
[ -f "$work/local/runs.csv" ] || fail "the local sweep wrote no runs.csv"
"$vv" --cache "$cache" --sweep rate=0.5,3,2 --seeds 2 --steps 3 --slurm 2 --out "$work/out" "$model" \
  > "$work/submit.log" 2>&1 || fail "--slurm failed: $(cat "$work/submit.log")"
grep -q "^submitted job array" "$work/submit.log" || fail "not submitted: $(cat "$work/submit.log")"
done=0
for i in $(seq 1 240); do
  if [ -z "$(squeue -h 2> /dev/null)" ]; then done=1; break; fi
  sleep 0.5
done
[ $done = 1 ] || fail "the jobs did not end in 120 s: $(squeue 2>&1)"
cmp -s "$work/local/runs.csv" "$work/out/runs.csv" || fail "runs.csv differs from the local sweep's"
cmp -s "$work/local/failed.csv" "$work/out/failed.csv" || fail "failed.csv differs from the local sweep's"
echo "slurm_single_node: passed: the sweep through Slurm merged to the local sweep's runs.csv and failed.csv"
