#!/usr/bin/env bash
# Installs what is missing (Debian packages only) and builds swingsim into build/.
# Usage: bash scripts/bootstrap.sh [extra cmake args]
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(build-essential cmake ccache libeigen3-dev libyaml-cpp-dev libgtest-dev libgmock-dev libbenchmark-dev
          nlohmann-json3-dev libboost-math-dev libcli11-dev libceres-dev libtinyxml2-dev libmuparser-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-venv python3-pip python3-setuptools python3-wheel
          universal-ctags clang-format
          libcpp-httplib-dev chromium chromium-driver python3-selenium
          jupyter-nbconvert python3-ipykernel python3-matplotlib)
bash scripts/install-packages.sh "${packages[@]}"
bash scripts/configure.sh build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j"$(nproc)"
