#!/usr/bin/env bash
# CI: install, build and run the whole test suite (CTest over GoogleTest) twice:
#   1. build/       Release, as users build it; then the Slurm proof (scripts/slurm-local.sh);
#   2. build-asan/  AddressSanitizer + UndefinedBehaviorSanitizer on the libraries and the
#                   command line (-O1 -g1; CMakeLists.txt): any report (memory error, leak,
#                   undefined behaviour) fails the run. The test programs' own files are
#                   compiled as in build/, uninstrumented, so ccache (configure.sh) hands
#                   build/'s objects over: this pass compiles the libraries only.
#                   Our code is compiled with NDEBUG there too (as everything that includes
#                   Simbody's headers must be) and linked to the same Release Simbody of
#                   scripts/simbody.sh: the sanitizers instrument our code, not Simbody's.
# Sanitizer reports exit with code 86, so a CLI test expecting exit code 1 (bad input)
# cannot mistake a crashed child for a clean refusal.
# Known reports from outside our code are suppressed, one documented line each, in
# scripts/sanitizer-suppressions/ (never blanket-disabled).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage's wall time on stderr ("== stage: N s"), the figures docs/install.md quotes.
stage_start=$SECONDS
stage() { echo "== $1: $((SECONDS - stage_start)) s" >&2; stage_start=$SECONDS; }
bash scripts/bootstrap.sh
stage "install and build (build/)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
stage "tests (build/)"

# The cohort example through a real one-node Slurm (examples/slurm/README.md): installs
# slurm-wlm and munge, starts the daemons itself, submits the job array and the merge, checks
# the merged result equals the one-machine run byte for byte, cancels and resumes one task,
# stops the daemons. About 1 min on 2 cores; needs root (CI runs as root).
echo "== Slurm: the cohort example on a one-node cluster (scripts/slurm-local.sh)" >&2
bash scripts/slurm-local.sh
stage "Slurm"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)" >&2
# At most 2 jobs: sanitized compiles and tests take 2-3x the memory of plain ones.
jobs=$(( $(nproc) < 2 ? $(nproc) : 2 ))
# Release as build/ (the test files' flags must match it); the libraries add their own.
bash scripts/configure.sh build-asan -DSWINGSIM_SANITIZE=ON -DSWINGSIM_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Release
supp="$PWD/scripts/sanitizer-suppressions"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:exitcode=86"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:exitcode=86:suppressions=$supp/ubsan.supp"
export LSAN_OPTIONS="exitcode=86:suppressions=$supp/lsan.supp"
# Also sanitized: the test discovery run of swingsim_tests at build time.
cmake --build build-asan -j"$jobs"
stage "build (build-asan/)"
if command -v ccache >/dev/null; then ccache --show-stats 2>/dev/null | grep -iE "hits|misses" >&2 || true; fi
ctest --test-dir build-asan --output-on-failure -j"$jobs"
stage "tests (build-asan/)"
