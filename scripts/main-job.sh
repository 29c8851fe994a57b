#!/usr/bin/env bash
# The main job: install, build, and run the Burkett 2004 knee-axis sweep study, then how sure
# its fastest lowering is (200 Monte Carlo samples over the unpublished assumptions and each
# assumption at both ends of its range: docs/uncertainty.md; 18,900 swings, 14 s on
# 2 cores). Writes out/burkett2004/report.md (+ CSV, SVG, JSON).
# Then the loop on the sweep itself: which effect, shared by the runners, explains Burkett's
# measured Table 4 (docs/diagnosis.md, "The sweep"; about 40 s) -> out/burkett2004-table4/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
build/swingsim sweep studies/burkett2004.yaml --json out/burkett2004/sweep.json --uncertainty 200 --seed 1
build/swingsim diagnose studies/burkett2004-table4.yaml --json out/burkett2004-table4/diagnosis.json
