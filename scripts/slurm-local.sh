#!/usr/bin/env bash
# A real one-node Slurm cluster on this machine, to prove the examples/slurm/ job array and
# its dependent merge job (examples/slurm/README.md). It installs Debian's slurm-wlm and munge if
# missing, writes a private configuration under WORK (localhost, 2 CPUs; no systemd or
# cgroups: proctrack/linuxproc, task/none; a munge key made here), starts munged, slurmctld
# and slurmd itself (loopback only, ports PORT and PORT+1), then:
#   1. runs the cohort study on this machine in one process (the reference result);
#   2. submits examples/slurm/submit.sh (SHARDS array tasks, the merge after them, afterok),
#      waits, and checks the merged report, CSV, figures and JSON equal the reference byte
#      for byte;
#   3. resume: submits one array task again into a fresh folder, cancels it with scancel
#      while it runs (swingsim keeps its finished participants in the shard file), submits
#      the same task again and the merge after it, and checks the result equals the
#      reference byte for byte;
# prints the wall time and swings per second of each step, and stops the daemons it started
# (also on failure or Ctrl-C). Exit 0 only if every check passed.
#
# Usage, from the repository root with build/swingsim built:
#   bash scripts/slurm-local.sh [STUDY]     (default studies/cohort-example.yaml)
# Environment: SHARDS (4), WORK (a new folder under /tmp), PORT (16817), SWINGSIM (build/swingsim).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
study="$(realpath "${1:-$root/studies/cohort-example.yaml}")"
shards="${SHARDS:-4}"
port="${PORT:-16817}"
swingsim="$(realpath "${SWINGSIM:-$root/build/swingsim}")"
work="${WORK:-$(mktemp -d /tmp/swingsim-slurm.XXXXXX)}"
[ -x "$swingsim" ] || { echo "slurm-local: $swingsim: not built (cmake --build build --target swingsim)" >&2; exit 1; }

bash "$root/scripts/install-packages.sh" slurm-wlm munge

mkdir -p "$work/state" "$work/spool" "$work/logs"
work="$(realpath "$work")"
host="$(hostname -s)"
export SLURM_CONF="$work/slurm.conf"
started=()  # pid files of the daemons this script started

stop_daemons() {
  local f pids=() p
  for f in "${started[@]}"; do
    [ -f "$f" ] && pids+=("$(cat "$f")")
  done
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do  # wait (up to 30 s each) until they are gone
    for _ in $(seq 1 150); do kill -0 "$p" 2>/dev/null || break; sleep 0.2; done
  done
  echo "slurm-local: stopped the daemons it started (${#pids[@]}); logs in $work"
}
trap stop_daemons EXIT

# ---- munge: a key of our own, a private socket ------------------------------------------------
dd if=/dev/urandom of="$work/munge.key" bs=1 count=1024 status=none
chmod 400 "$work/munge.key"
# --force: munged runs as root here (the whole cluster is this script's).
munged --force --key-file="$work/munge.key" --socket="$work/munge.socket" --pid-file="$work/munged.pid" \
  --log-file="$work/logs/munged.log" --seed-file="$work/munged.seed"
started+=("$work/munged.pid")

cat > "$SLURM_CONF" <<CONF
ClusterName=swingsim
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
ReturnToService=2
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/logs/slurmctld.log
SlurmdLogFile=$work/logs/slurmd.log
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MinJobAge=3600
KillWait=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=2 RealMemory=2000 State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -f "$SLURM_CONF"
started+=("$work/slurmctld.pid")
slurmd -f "$SLURM_CONF"
started+=("$work/slurmd.pid")
for _ in $(seq 1 30); do
  sinfo -h -o %t 2>/dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o %t | grep -q idle || { echo "slurm-local: the node did not come up (logs in $work/logs)" >&2; exit 1; }
echo "slurm-local: one-node cluster up: $(sinfo -h -o '%P %D node(s) %c CPUs %t')"

# ---- helpers -----------------------------------------------------------------------------------
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }
# Waits until none of the given jobs is pending or running.
wait_jobs() {
  while [ -n "$(squeue -h -j "$(IFS=,; echo "$*")" 2>/dev/null)" ]; do sleep 1; done
}
job_state() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1; }
# Swings simulated for the shard files given: each participant's calibration and its lowerings.
count_swings() { /usr/bin/python3 - "$@" <<'PY'
import json, sys
n = 0
for path in sys.argv[1:]:
    for r in json.load(open(path))["results"]:
        n += r.get("calibration_swings", 0) + len(r.get("lowerings_m", []))
print(n)
PY
}
compare() {  # reference folder, result folder, the result's JSON name
  local ok=0 f
  for f in report.md cohort.csv cohort-fastest-lowering.svg cohort-time-gained.svg cohort-predictors.svg; do
    cmp -s "$1/$f" "$2/$f" || { echo "slurm-local: $2/$f differs from the one-machine run" >&2; ok=1; }
  done
  cmp -s "$1/cohort.json" "$2/$3" || { echo "slurm-local: $2/$3 differs from the one-machine cohort.json" >&2; ok=1; }
  [ "$(ls "$1"/cohort-gain-vs-*.svg)" ] && for f in "$1"/cohort-gain-vs-*.svg; do
    cmp -s "$f" "$2/$(basename "$f")" || { echo "slurm-local: $2/$(basename "$f") differs" >&2; ok=1; }
  done
  return $ok
}

# ---- 1. the one-machine reference --------------------------------------------------------------
cd "$work"
t0=$(now)
"$swingsim" sweep "$study" --out "$work/one" --json "$work/one/cohort.json" --jobs 2 > "$work/logs/one.stdout" 2> "$work/logs/one.stderr"
t1=$(now)
participants=$(/usr/bin/python3 -c "import json; print(json.load(open('$work/one/cohort.json'))['participants'])")
echo "slurm-local: one machine: $participants participants in $(elapsed "$t0" "$t1") s"

# ---- 2. the job array and the dependent merge through sbatch ---------------------------------
export STUDY="$study" SAMPLES=0 SHARDS="$shards" OUT="$work/slurm" SWINGSIM="$swingsim"
t2=$(now)
submitted=$(bash "$root/examples/slurm/submit.sh")
echo "slurm-local: $submitted"
array=$(echo "$submitted" | sed -n 's/.*array job \([0-9]*\).*/\1/p')
merge=$(echo "$submitted" | sed -n 's/.*merge as job \([0-9]*\).*/\1/p')
wait_jobs "$array" "$merge"
t3=$(now)
[ "$(job_state "$merge")" = COMPLETED ] || { echo "slurm-local: merge job $merge ended $(job_state "$merge")" >&2; exit 1; }
swings=$(count_swings "$work"/slurm/shards/cohort-shard-*-of-"$shards".json)
compare "$work/one" "$work/slurm" sweep.json
echo "slurm-local: Slurm array of $shards + merge: $(elapsed "$t2" "$t3") s wall; the merged result equals the one-machine run byte for byte"

# ---- 3. resume after a cancelled array task ----------------------------------------------------
k=$((shards / 2))
export OUT="$work/resume"
mkdir -p "$OUT/shards"
for f in "$work"/slurm/shards/cohort-shard-*-of-"$shards".json; do  # the other tasks, already done
  case "$f" in *"-shard-$k-of-"*|*"-shard-0$k-of-"*) ;; *) cp "$f" "$OUT/shards/" ;; esac
done
t4=$(now)
task=$(sbatch --parsable --array="$k" "$root/examples/slurm/shard.sbatch")
task=${task%%;*}
# Cancel it once its progress line shows a participant or more done (none = nothing to resume).
log="$work/slurm-swingsim-shard-${task}_$k.out"
for _ in $(seq 1 600); do
  grep -Eq ' [1-9][0-9]*/[0-9]+ participants' "$log" 2>/dev/null && break
  sleep 0.1
done
scancel "${task}_$k" 2>/dev/null || scancel "$task"
wait_jobs "$task"
shardfile=$(ls "$OUT"/shards/cohort-shard-*"$k"-of-"$shards".json)
partial=$(/usr/bin/python3 -c "import json; d=json.load(open('$shardfile')); print(d['partial'], d['participants_finished'], len(d['results']))")
echo "slurm-local: task $k cancelled while running ($(job_state "$task")): its shard file says partial, finished, of: $partial"
case "$partial" in True*) ;; *) echo "slurm-local: the task finished before scancel reached it; the resume was not exercised" >&2; exit 1 ;; esac
again=$(sbatch --parsable --array="$k" "$root/examples/slurm/shard.sbatch")
again=${again%%;*}
merge2=$(sbatch --parsable --dependency=afterok:"$again" "$root/examples/slurm/merge.sbatch")
merge2=${merge2%%;*}
wait_jobs "$again" "$merge2"
t5=$(now)
[ "$(job_state "$merge2")" = COMPLETED ] || { echo "slurm-local: merge job $merge2 ended $(job_state "$merge2")" >&2; exit 1; }
grep -q "resuming from" "$work"/slurm-swingsim-shard-"${again}"_"$k".out \
  || { echo "slurm-local: the resubmitted task did not resume from the cancelled one's file" >&2; exit 1; }
compare "$work/one" "$OUT" sweep.json
echo "slurm-local: resume: task $k cancelled, resubmitted, merged: $(elapsed "$t4" "$t5") s wall; equal to the one-machine run byte for byte"

echo "slurm-local: summary: $participants participants, $swings swings (calibrations and lowerings);" \
  "one machine $(elapsed "$t0" "$t1") s ($(awk -v n="$swings" -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", n / (b - a) }') swings/s)," \
  "Slurm $(elapsed "$t2" "$t3") s ($(awk -v n="$swings" -v a="$t2" -v b="$t3" 'BEGIN { printf "%.0f", n / (b - a) }') swings/s)," \
  "whole script $(elapsed "$t0" "$t5") s after the daemons came up"
