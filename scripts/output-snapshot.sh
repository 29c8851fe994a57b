#!/usr/bin/env bash
# Runs every shipped study, demo and command once and keeps every file they write and every line
# they print, so that a refactoring can be checked to change no output: run it on the commit
# before and after and compare the two folders byte for byte.
# Usage: bash scripts/output-snapshot.sh BUILD_DIR SNAPSHOT_DIR
#        diff -r SNAPSHOT_BEFORE SNAPSHOT_AFTER
# Takes about 4 minutes on 2 cores (the main job's 200-sample uncertainty analysis is in it).
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(cd "$1" && pwd)/swingsim"
snap="$2"
rm -rf "$snap"
mkdir -p "$snap"
snap="$(cd "$snap" && pwd)"

# run NAME ARGS...: stdout, stderr and exit code, with the snapshot folder's path blanked and the
# progress lines (which count what finished by a time, so vary run to run) left out.
run() {
  local name="$1"; shift
  local rc=0
  "$bin" "$@" >"$snap/$name.stdout" 2>"$snap/$name.stderr" || rc=$?
  echo "$rc" >"$snap/$name.rc"
  sed -i "s|$snap|SNAP|g" "$snap/$name.stdout" "$snap/$name.stderr"
  sed -i -E '/\([0-9]+ %\)/d' "$snap/$name.stderr"
}

for s in burkett2004 burkett2004-mauch burkett2004-measured burkett2004-proportional-com; do
  run "sweep-$s" sweep "studies/$s.yaml" --jobs 2 --out "$snap/$s" --json "$snap/$s/sweep.json"
done
run sweep-uncertainty sweep studies/burkett2004.yaml --jobs 2 --uncertainty 200 --seed 1 \
  --out "$snap/uncertainty" --json "$snap/uncertainty/sweep.json"
run shard-1 sweep studies/burkett2004.yaml --jobs 2 --uncertainty 40 --seed 3 --shard 0/2 \
  --out "$snap/shards"
run shard-2 sweep studies/burkett2004.yaml --jobs 2 --uncertainty 40 --seed 3 --shard 1/2 \
  --out "$snap/shards"
run merge merge "$snap"/shards/*.json --out "$snap/merged" --json "$snap/merged/sweep.json"
run cohort sweep studies/cohort-example.yaml --jobs 2 --out "$snap/cohort" \
  --json "$snap/cohort/sweep.json"
run add-mass sweep studies/burkett2004.yaml --jobs 2 --add-mass 0.5@0.2 --out "$snap/add-mass" \
  --json "$snap/add-mass/sweep.json"

for s in burkett2004-table4 diagnose-demo-cylinder diagnose-demo-swing \
         opensim-subject01-walk opensim-subject01-walk-fixed-hip winter-swing; do
  run "diagnose-$s" diagnose "studies/$s.yaml" --out "$snap/diagnose-$s" \
    --json "$snap/diagnose-$s/diagnosis.json"
done
for s in diagnose-demo-cylinder diagnose-demo-swing; do
  run "save-model-$s" diagnose "studies/$s.yaml" --out "$snap/save-model-$s" \
    --save-model "$snap/save-model-$s/model.yaml"
done
for s in diagnose-demo-swing winter-swing opensim-subject01-walk; do
  run "compare-$s" compare "studies/$s.yaml" --out "$snap/compare-$s" \
    --json "$snap/compare-$s/comparison.json"
done
run fit fit studies/mauch2014.yaml --out "$snap/fit" --json "$snap/fit/fit.json"
for s in mauch2014-bench diagnose-demo-cylinder-bench diagnose-demo-swing-data; do
  run "generate-$s" generate "studies/$s.yaml" --out "$snap/generate-$s"
done

for p in p1 p2 p3 p4 winter opensim-subject01; do
  run "simulate-$p" simulate "participants/$p.yaml" --out "$snap/simulate-$p" \
    --json "$snap/simulate-$p/simulate.json"
done
run simulate-mauch simulate participants/p1.yaml --knee models/mauch-4phase.yaml --lowering 0.02 \
  --add-mass 0.5@0.2 --out "$snap/simulate-mauch" --json "$snap/simulate-mauch/simulate.json"
run calibrate calibrate participants/p1.yaml participants/p3.yaml --dry-run

d=tests/data/opensim-running
run swings-walk swings tests/data/opensim-gait10dof/subject01_walk_IK.mot --json "$snap/swings-walk.json"
run swings-hamner swings $d/hamner_subject02_running_ik.mot --grf $d/hamner_subject02_running_grf.mot \
  --json "$snap/swings-hamner.json"
run swings-rajagopal swings $d/rajagopal_subject01_run_ik.mot --knee-sign 1 --grf $d/rajagopal_grf_run.mot \
  --vertical-force R_ground_force_vy \
  --json "$snap/swings-rajagopal.json"
run swings-other-foot swings $d/hamner_subject02_running_ik.mot --side l \
  --grf $d/hamner_subject02_running_grf.mot
run import-osim import-osim studies/data/opensim-subject01/gait2354_subject01_simbody.osim --side r
run export-osim export-osim participants/p1.yaml --lowering 0.05 --out "$snap/export-osim"

# Paths in written files name the snapshot folder: blank it so two snapshots compare.
grep -rl --null "$snap" "$snap" | xargs -0 -r sed -i "s|$snap|SNAP|g"
echo "snapshot: $snap ($(find "$snap" -type f | wc -l) files)"
