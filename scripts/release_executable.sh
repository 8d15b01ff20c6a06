#!/usr/bin/env bash
# For the study scripts: prints the path of the executable to time. With an
# argument, that executable (made absolute); without, the Release build's
# build/ddcontact, after installing what is missing and building it (the
# build's output goes to stderr).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ge 1 ] && [ -n "$1" ]; then
  realpath "$1"
  exit 0
fi
{
  scripts/install_deps.sh
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C build ddcontact
} 1>&2
realpath build/ddcontact
