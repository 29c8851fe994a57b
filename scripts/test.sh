#!/usr/bin/env bash
# Install, build, and run the whole test suite (CTest over GoogleTest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/bootstrap.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
