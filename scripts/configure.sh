#!/usr/bin/env bash
# Configures a swingsim build directory against the Release Simbody of scripts/simbody.sh
# (built once into a cache, then reused). The one place every build finds Simbody: bootstrap.sh
# (build/), test.sh (build-asan/), bench.sh (build-perf/) and fuzz.sh (build-fuzz/) call it.
# Usage: bash scripts/configure.sh BUILD_DIR [extra cmake args]
set -euo pipefail
cd "$(dirname "$0")/.."
dir="$1"; shift
prefix="$(bash scripts/simbody.sh)"
# Debian's ccache (installed by bootstrap.sh) in front of the compiler when it is there, its
# cache in ccache's own folder beside Simbody's (~/.cache/ccache): a rebuild of an unchanged
# file, in another clone or after `rm -rf build`, is a cache hit (docs/install.md gives the
# cost of a fresh and a warm machine). SWINGSIM_CCACHE=0 builds without it.
launcher=()
if [ "${SWINGSIM_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$dir" -DSWINGSIM_SIMBODY_PREFIX="$prefix" "${launcher[@]}" "$@" >/dev/null
