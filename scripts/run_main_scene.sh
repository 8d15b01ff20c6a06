#!/usr/bin/env bash
# Set-up command 1 of the README: installs what is missing, builds the
# Release executable at build/ddcontact and runs the main scene end to end.
# Extra arguments are passed to ddcontact (e.g. --output DIR).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
ninja -C build ddcontact
build/ddcontact "$@" prm/paper_two_bodies.prm
