#!/usr/bin/env bash
# Set-up command 2 of the README: installs what is missing, builds the test
# suite in Debug (every deal.II Assert checked) under build-debug/ and runs
# the default set with ctest (every test without the label long).
#   scripts/run_tests.sh            the default set
#   scripts/run_tests.sh --long     the label long: the full fuzz run, the
#                                   studies' smoke tests, the refinement
#                                   study of the penalty continuation and
#                                   the sanitizer build
#   scripts/run_tests.sh --all      both
# Further arguments are passed to ctest (e.g. -R hertz).
set -euo pipefail
cd "$(dirname "$0")/.."

selection=(-LE long)
case "${1:-}" in
  --long) selection=(-L long); shift ;;
  --all) selection=(); shift ;;
esac

scripts/install_deps.sh
# Asserts, not a debugger, are what this build is for: no debug
# information (DDCONTACT_DEBUG_INFO, a quarter off every compile).
cmake -S . -B build-debug -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DDDCONTACT_DEBUG_INFO=OFF >/dev/null
ninja -C build-debug
cd build-debug
ctest --output-on-failure -j 2 "${selection[@]}" "$@"
