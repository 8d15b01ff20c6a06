#!/usr/bin/env bash
# Builds the library, the executable and the fast tests with AddressSanitizer
# and UndefinedBehaviorSanitizer in a build directory of their own (our code instrumented,
# linked against Debian's Release deal.II) and runs the fast tests under
# them: any invalid access, leak of a stack object, signed overflow, bad
# shift or misaligned load in our code ends the test with a report.
# The ctest "sanitizers" (label long) runs it with its build directory as the
# argument (default: build-asan/); doc/reliability.md says what it covers.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build-asan}"

scripts/install_deps.sh
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -g -O1"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null

# The fast tests: seconds each, together covering parsing, the bad-input
# checks, the contact pair and DD, the relaxations and the BEM kernels.
tests=(relaxation contact_law boundary_conditions json patch_test flat_punch contact_dd bem_kernels bem_patch bem_hanging_nodes bad_input)
targets=(ddcontact)
for t in "${tests[@]}"; do
  [ "$t" = bad_input ] || targets+=("test_$t")
done
ninja -C "$build" "${targets[@]}"

# Leak checking is off: OpenMPI and TBB keep allocations until exit, which
# LeakSanitizer reports as leaks of libraries we do not control.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=0:halt_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
regex="^($(IFS='|'; echo "${tests[*]}"))\$"
ctest --output-on-failure -j 2 -R "$regex"
