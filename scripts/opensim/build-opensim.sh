#!/usr/bin/env bash
# Builds OpenSim's core libraries (osimCommon, osimSimulation; no Moco, no apps, no bindings)
# and the Simbody they pin, then scripts/opensim/check_exported_model.cpp against them, so that
# OpenSim itself can open a model written by `swingsim export-osim` and play a motion on it.
# Not part of the build or CI: over an hour on 2 cores (docs/opensim-check.md).
#
# Usage: bash scripts/opensim/build-opensim.sh OPENSIM_CORE_GIT_DIR SIMBODY_GIT_DIR [WORK_DIR]
#   OPENSIM_CORE_GIT_DIR  a clone (or bare mirror) of github.com/opensim-org/opensim-core
#   SIMBODY_GIT_DIR       a clone (or bare mirror) of github.com/simbody/simbody
#   WORK_DIR              where the sources, the builds and the checker go (default ~/opensim-check)
# Then: WORK_DIR/check_exported_model MODEL.osim [MOTION.sto ...]
#
# Which OpenSim: commit a03dcb61b (the merge of OpenSim 4.5.2). Later commits include <format>
# (C++20), which Debian 12's GCC 12 lacks. OpenSim 4.5.2 calls Simbody's
# GeneralForceSubsystem::calcForceContributionsSum, which Simbody 3.7 (swingsim's, Debian's)
# lacks, so the Simbody OpenSim pins (dependencies/CMakeLists.txt: f260ff3, 3.8) is built too.
# One local change makes 4.5.2 build with Debian's spdlog: libspdlog-dev 1.10 uses the external
# fmt 9 (libfmt-dev), not a bundled copy, so includes of <spdlog/fmt/bundled/X.h> become
# <fmt/X.h> (base.h becomes core.h).
set -euo pipefail
src_git=${1:?usage: build-opensim.sh OPENSIM_CORE_GIT_DIR SIMBODY_GIT_DIR [WORK_DIR]}
simbody_git=${2:?usage: build-opensim.sh OPENSIM_CORE_GIT_DIR SIMBODY_GIT_DIR [WORK_DIR]}
work=${3:-$HOME/opensim-check}
commit=a03dcb61b
simbody_commit=f260ff30381826728da721226151e733715d0df9
here="$(cd "$(dirname "$0")" && pwd)"
bash "$here/../install-packages.sh" libspdlog-dev libfmt-dev liblapack-dev libblas-dev
mkdir -p "$work"
if [ ! -d "$work/simbody" ]; then
  mkdir -p "$work/simbody-src" "$work/simbody-build"
  # Windows binaries and the theory manual may be absent from a partial mirror; not needed.
  git -C "$simbody_git" archive "$simbody_commit" -- . ':!Platform/Windows' \
      ':!Simbody/doc/SimbodyTheoryManual.docx' ':!Simbody/doc/SimbodyTheoryManual.pdf' |
      tar -x -C "$work/simbody-src"
  cmake -S "$work/simbody-src" -B "$work/simbody-build" -DCMAKE_BUILD_TYPE=Release \
        -DBUILD_VISUALIZER=OFF -DBUILD_EXAMPLES=OFF -DBUILD_TESTING=OFF \
        -DCMAKE_INSTALL_PREFIX="$work/simbody" >/dev/null
  cmake --build "$work/simbody-build" --target install -j"$(nproc)"
fi
if [ ! -d "$work/opensim-core" ]; then
  mkdir -p "$work/opensim-core"
  # Large test resources may be absent from a partial mirror: leave out what cannot be read.
  git -C "$src_git" archive "$commit" -- . ':!Applications/Analyze/test/subject02_running_CMC_states.sto' |
      tar -x -C "$work/opensim-core"
  grep -rl "spdlog/fmt/bundled" "$work/opensim-core/OpenSim" |
      xargs sed -i 's|spdlog/fmt/bundled/base.h|fmt/core.h|; s|spdlog/fmt/bundled/|fmt/|'
fi
mkdir -p "$work/build"
cmake -S "$work/opensim-core" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
      -DSIMBODY_HOME="$work/simbody" -DOPENSIM_WITH_CASADI=OFF -DBUILD_TESTING=OFF \
      -DBUILD_API_EXAMPLES=OFF -DBUILD_PYTHON_WRAPPING=OFF -DBUILD_JAVA_WRAPPING=OFF \
      -DOPENSIM_C3D_PARSER=None >/dev/null
cmake --build "$work/build" --target osimSimulation -j"$(nproc)"

o="$work/opensim-core"; b="$work/build"   # the libraries land at the top of the build folder
g++ -std=c++17 -O2 -o "$work/check_exported_model" "$here/check_exported_model.cpp" \
    -DSPDLOG_FMT_EXTERNAL -DSPDLOG_COMPILED_LIB -DSPDLOG_SHARED_LIB -DFMT_SHARED \
    -I"$o" -I"$o/Vendors/lepton/include" -isystem "$work/simbody/include/simbody" \
    -L"$b" -L"$work/simbody/lib" \
    -losimSimulation -losimCommon -losimLepton -lSimTKsimbody -lSimTKmath -lSimTKcommon \
    -lspdlog -lfmt -Wl,-rpath,"$b:$work/simbody/lib"
echo "built $work/check_exported_model" >&2
