#!/usr/bin/env bash
# The Slurm test of the workflow (ctest label `cluster`, not part of the default tests): starts a
# single-node Slurm on this machine (Debian's slurm-wlm and munge, installed if missing;
# configuration in a temporary directory: munged, slurmctld and slurmd started directly,
# proctrack/linuxproc, task/none, no accounting), runs the `quick` level of the main job through
# Snakemake with the Slurm profile (workflow/profiles/slurm: every job an sbatch job), checks
# that every job ran under Slurm and passed and that the report was written, and stops the
# daemons (also on failure or interrupt). Needs root (the daemons, apt).
#
# Usage: scripts/run-cluster-test.sh [build-dir]   (default: build-cluster; configured and built here)
# Exit status 0 when the whole quick level passed through Slurm.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$(pwd)
build=${1:-build-cluster}
start=$(date +%s)
if [[ $(id -u) -ne 0 ]]; then echo "run-cluster-test: needs root (starts munged, slurmctld, slurmd)" >&2; exit 2; fi
scripts/install-deps.sh --report
scripts/install-deps.sh --cluster
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
build=$(realpath "$build")

tmp=$(mktemp -d /tmp/ibms-slurm.XXXXXX)
host=$(hostname -s)
cpus=$(nproc)
# Memory the node offers to jobs: half of this machine's, at most 16 GB.
mem=$(awk '/MemTotal/ {m = int($2 / 1024 / 2); if (m > 16000) m = 16000; print m}' /proc/meminfo)
# Free ports for slurmctld and slurmd (two that nothing listens on).
ports=$(/usr/bin/python3 -c 'import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(" ".join(str(x.getsockname()[1]) for x in s))')
read -r ctld_port slurmd_port <<< "$ports"
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/munge"
chmod 700 "$tmp/munge"

stop() {
  local rc=$?
  for d in slurmd slurmctld munged; do
    if [[ -f $tmp/$d.pid ]]; then kill "$(cat "$tmp/$d.pid")" 2>/dev/null || true; fi
  done
  sleep 1
  for d in slurmd slurmctld munged; do
    if [[ -f $tmp/$d.pid ]] && kill -0 "$(cat "$tmp/$d.pid")" 2>/dev/null; then kill -9 "$(cat "$tmp/$d.pid")" || true; fi
  done
  if [[ $rc -ne 0 ]]; then
    echo "run-cluster-test: failed (exit $rc); Slurm logs:" >&2
    tail -n 20 "$tmp"/slurmctld.log "$tmp"/slurmd.log >&2 2>/dev/null || true
  fi
  rm -rf "$tmp"
  echo "run-cluster-test: daemons stopped, $tmp removed ($(( $(date +%s) - start )) s in all)"
}
trap stop EXIT
trap 'exit 130' INT TERM

# MUNGE with its own key, socket and files (a running system munged is left alone).
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
munged --force --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
       --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munge/munge.seed"
export MUNGE_SOCKET="$tmp/munge/munge.socket"

cat > "$tmp/slurm.conf" <<EOF
ClusterName=ibmstest
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
# a backfill pass every 5 s (default 30): most jobs here last seconds
SchedulerParameters=bf_interval=5
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"
slurmctld
slurmd
for i in $(seq 1 30); do
  if sinfo -h -o %T 2>/dev/null | grep -q idle; then break; fi
  sleep 1
done
sinfo
if ! sinfo -h -o %T | grep -q idle; then echo "run-cluster-test: the node did not come up" >&2; exit 1; fi

echo "== quick level through Slurm (workflow/profiles/slurm)"
# The Slurm test is a fresh run: the workflow's status files and the report of this build go.
rm -rf "$build/workflow_state" "$build/ibms_validation_report.pdf" "$build/validation/results.csv" "$build/sweeps"
wf_start=$(date +%s)
status=0
snakemake -s workflow/Snakefile --directory "$build" --configfile workflow/config/quick.yaml \
  --config build="$build" node_cores="$cpus" --profile workflow/profiles/slurm || status=1
wf_seconds=$(( $(date +%s) - wf_start ))
echo "== checks"
/usr/bin/python3 workflow/ibms_workflow.py summary "$build" || status=1
# Every job except the local ones ran as an sbatch job on the node (their logs name it).
jobs_run=$(ls "$build"/workflow_state/slurm/ibms-*.out 2>/dev/null | wc -l)
hosts=$(/usr/bin/python3 -c 'import glob, json, sys
print(" ".join(sorted({json.load(open(p)).get("host", "?") for p in glob.glob(sys.argv[1] + "/workflow_state/tests/*.status")})))' "$build")
echo "sbatch jobs: $jobs_run (logs in $build/workflow_state/slurm/), hosts of the case jobs: $hosts"
[[ $jobs_run -gt 0 ]] || { echo "run-cluster-test: no job went through sbatch" >&2; status=1; }
[[ -s $build/ibms_validation_report.pdf ]] || { echo "run-cluster-test: no report" >&2; status=1; }
[[ -s $build/validation/results.csv ]] || { echo "run-cluster-test: no results.csv" >&2; status=1; }
if grep -q ",FAIL" "$build/validation/results.csv" 2>/dev/null; then
  echo "run-cluster-test: failing checks in results.csv" >&2; status=1
fi
echo "run-cluster-test: quick level through Slurm $([[ $status -eq 0 ]] && echo passed || echo FAILED) in $wf_seconds s (workflow only)"
exit $status
