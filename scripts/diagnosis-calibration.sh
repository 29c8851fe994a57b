#!/usr/bin/env bash
# The calibration study of the diagnosis (docs/diagnosis.md, "How far the intervals can be
# trusted (calibration)"): every swing, cylinder and sweep candidate hidden in data from the
# independent generators (tests/independent/), plus nulls, diagnosed over N noise seeds; per
# candidate the named rate, other effects named, false acceptances on nulls, the 95 %
# interval's coverage of the truth, and the estimate's bias and spread.
# Usage: bash scripts/diagnosis-calibration.sh [--build DIR] [--seeds N] [--first S] [--jobs J]
#        [--only PLANT/EFFECT-SUBSTRING[,...]] [--out DIR]   (a sweep diagnosis costs about 30 s CPU)
#   defaults: build, 20 seeds from 1, jobs = number of cores, out/calibration
# Writes OUT/calibration.md (the table), OUT/calibration.csv (a row a case) and
# OUT/calibration-seeds.csv (a row a seed), and prints the wall time.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build"
args=()
out="$root/out/calibration"
seeds=20
jobs="$(nproc)"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --first|--only) args+=("$1" "$2"); shift 2 ;;
    *) echo "diagnosis-calibration: unknown option $1" >&2; exit 2 ;;
  esac
done
program="$build/diagnosis_calibration"
if [ ! -x "$program" ]; then
  echo "diagnosis-calibration: $program is missing: cmake --build $build --target diagnosis_calibration" >&2
  exit 1
fi
start=$(date +%s)
"$program" --seeds "$seeds" --jobs "$jobs" --out "$out" ${args[@]+"${args[@]}"}
end=$(date +%s)
echo "diagnosis-calibration: $seeds seeds, $jobs jobs, $((end - start)) s wall ($(date -u +%Y-%m-%d))"
cat "$out/calibration.md"
