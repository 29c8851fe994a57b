#!/bin/bash
# Submits a sweep's uncertainty analysis to Slurm: a job array of SHARDS tasks
# (shard.sbatch, `swingsim sweep --shard K/SHARDS`), then the merge (merge.sbatch), which
# starts only when every task has succeeded (--dependency=afterok). Run from the
# repository's root on the cluster's login node, with swingsim built and the study,
# participant and knee model files on a file system every node sees:
#
#   STUDY=studies/burkett2004.yaml SAMPLES=1000 SEED=1 SHARDS=20 OUT=out/burkett2004-slurm \
#     bash examples/slurm/submit.sh
#
# A cohort study (kind: cohort-sweep, docs/cohort.md) takes SAMPLES=0: its own seed draws its
# participants, and each shard computes whole participants:
#
#   STUDY=studies/cohort-example.yaml SAMPLES=0 SHARDS=4 OUT=out/cohort-slurm bash examples/slurm/submit.sh
#
# The result is $OUT/report.md and $OUT/sweep.json, the same as one
# `swingsim sweep $STUDY --uncertainty $SAMPLES --seed $SEED --out $OUT --json $OUT/sweep.json`.
# Queue, account and time limits are the cluster's: add them to the #SBATCH lines or here.
set -euo pipefail

export STUDY="${STUDY:-studies/burkett2004.yaml}"
export SAMPLES="${SAMPLES:-1000}"
export SEED="${SEED:-1}"
export SHARDS="${SHARDS:-20}"
export OUT="${OUT:-out/burkett2004-slurm}"
export SWINGSIM="${SWINGSIM:-build/swingsim}"
here="$(cd "$(dirname "$0")" && pwd)"

array=$(sbatch --parsable --array=0-$((SHARDS - 1)) "$here/shard.sbatch")
array=${array%%;*}  # --parsable prints "jobid" or "jobid;cluster"
merge=$(sbatch --parsable --dependency=afterok:"$array" "$here/merge.sbatch")
echo "submitted: shards as array job $array (tasks 0-$((SHARDS - 1))), merge as job ${merge%%;*} after it"
