#!/usr/bin/env bash
# The main job: install, build, and run the Burkett 2004 knee-axis sweep study.
# Writes out/burkett2004/report.md (+ CSV, SVG, JSON).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
build/swingsim sweep studies/burkett2004.yaml --json out/burkett2004/sweep.json
