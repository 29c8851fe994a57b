#!/usr/bin/env bash
# Configures a swingsim build directory against the Release Simbody of scripts/simbody.sh
# (built once into a cache, then reused). The one place every build finds Simbody: bootstrap.sh
# (build/), test.sh (build-asan/), bench.sh (build-perf/) and fuzz.sh (build-fuzz/) call it.
# Usage: bash scripts/configure.sh BUILD_DIR [extra cmake args]
set -euo pipefail
cd "$(dirname "$0")/.."
dir="$1"; shift
prefix="$(bash scripts/simbody.sh)"
cmake -S . -B "$dir" -DSWINGSIM_SIMBODY_PREFIX="$prefix" "$@" >/dev/null
