#!/usr/bin/env bash
# A sweep run as a Slurm array job from its emitted lines alone, then --collect: the summary
# must equal a direct sweep's (wall time aside). The test starts its own single-node Slurm
# (Debian's slurm-wlm and munge): munged, slurmctld and slurmd as this test's processes on a
# generated configuration in a temporary folder, stopped by their PIDs at the end.
# Usage: slurm_sweep.sh GBSSN1D_EXECUTABLE. Exit 77 (skipped) when the packages are missing.
set -euo pipefail
exe=$1
for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo; do
  command -v "$tool" >/dev/null 2>&1 || PATH="$PATH:/usr/sbin"
  command -v "$tool" >/dev/null 2>&1 || { echo "skipped: $tool is not installed (slurm-wlm, munge)"; exit 77; }
done
tmp=$(mktemp -d /tmp/gbssn1d_slurm.XXXXXX)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  [ -f "$tmp/munged.pid" ] && kill "$(cat "$tmp/munged.pid")" 2>/dev/null || true
  sleep 0.5
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAILED: $*"; for f in "$tmp"/*.log; do echo "== $f"; tail -20 "$f"; done; exit 1; }
# Slurm that cannot start on this machine (the daemons, not gbssn1d) is reported as skipped,
# with its logs; everything after the node is up must pass
cannot_start() {
  echo "skipped: $* (the single-node Slurm could not be started here)"
  for f in "$tmp"/*.log; do echo "== $f"; tail -10 "$f"; done
  exit 77
}

# munge, with its own key and socket
mungekey --create --keyfile "$tmp/munge.key" --force >/dev/null 2>&1 \
  || dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 2>/dev/null
chmod 600 "$tmp/munge.key"
munged --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" --pid-file="$tmp/munged.pid" \
  --log-file="$tmp/munged.log" --seed-file="$tmp/munge.seed" --force \
  || cannot_start "munged did not start"

# a one-node cluster on free ports
port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
user=$(id -un)
node=$(hostname -s)
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/elsewhere"
cat >"$tmp/slurm.conf" <<CONF
ClusterName=gbssn1dtest
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$(port)
SlurmdPort=$(port)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out.log" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$tmp/slurmd.out.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do
  sinfo -h -o %T 2>/dev/null | grep -q idle && break
  sleep 0.2
done
sinfo -h -o %T 2>/dev/null | grep -q idle || cannot_start "the node did not become idle"

# the sweep: directly, and as an array job from the emitted lines
flags=(--sweep rahA=0.25,0.5 --sweep rah0=0.6,1.2 --id 1log-trumpet --grid uniform --N 100
       --rmax 20 --tmax 5 --dt-series 1)
"$exe" sweep -j 2 --out "$tmp/direct" "${flags[@]}" >/dev/null 2>&1 || fail "direct sweep"
(cd "$tmp" && "$exe" sweep --out queued "${flags[@]}" --emit-tasks tasks.txt >/dev/null 2>&1) \
  || fail "--emit-tasks"
n=$(wc -l <"$tmp/tasks.txt")
[ "$n" = 4 ] || fail "$n lines emitted, 4 expected"
job=$(cd "$tmp/elsewhere" && sbatch --parsable --array=1-"$n" --output="$tmp/array-%a.log" \
  --wrap "bash -c \"\$(sed -n \${SLURM_ARRAY_TASK_ID}p $tmp/tasks.txt)\"") || fail "sbatch"
for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.2
done
[ -z "$(squeue -h -j "$job" 2>/dev/null)" ] || fail "the array job did not finish"
"$exe" sweep --out "$tmp/queued" "${flags[@]}" --collect >/dev/null 2>&1 || fail "--collect"
python3 "$(dirname "$0")/same_summary.py" "$tmp/direct" "$tmp/queued" \
  || fail "the collected summary differs from the direct sweep's"
[ "$(grep -c " ok " "$tmp/queued/summary.dat")" = 4 ] || fail "not every member finished"
echo "a 2 x 2 sweep as Slurm array job $job: --collect equals the direct sweep"
