#!/usr/bin/env bash
# Set-up command 2 of the README: installs what is missing, builds the test
# suite in Debug (every deal.II Assert checked) under build-debug/ and runs it
# with ctest. Extra arguments are passed to ctest (e.g. -R hertz).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install_deps.sh
cmake -S . -B build-debug -G Ninja -DCMAKE_BUILD_TYPE=Debug >/dev/null
ninja -C build-debug
cd build-debug
ctest --output-on-failure -j 2 "$@"
