#!/usr/bin/env bash
# DESCRIPTION: an error under MPI is printed once and every process exits
# with its documented code (doc/reliability.md): a bad value given to
# process 1 alone (an MPMD launch) names process 1 and ends the run with
# exit 1; the same bad value on every process is printed once without a
# process number; different errors on the processes are each printed once
# with their processes; Parallel/Mesh = distributed where no mesh is split
# is refused in one line, and so is a solver that runs on one process
# usage: mpi_errors.sh MPIRUN DDCONTACT_EXECUTABLE SOURCE_DIR
set -u
mpirun="$1"; exe="$2"; src="$3"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failures=0
check() { # check CONDITION_EXIT_CODE WHAT
  if [ "$1" -eq 0 ]; then echo "ok   $2"; else echo "FAIL $2"; failures=$((failures + 1)); fi
}
count() { grep -c -- "$1" "$2"; }

good="$work/good.prm"
cp "$src/prm/paper_two_bodies.prm" "$good"
sed "s/set Poisson's ratio = 0.3/set Poisson's ratio = 0.7/" "$good" > "$work/nu.prm"
sed "s/set Young's modulus = .*/set Young's modulus = -1/" "$good" > "$work/E.prm"
nu="Poisson's ratio: nu = 0.7"

# 1. Process 1 alone: it cannot reach process 0 (waiting in the setup), so
# it prints its line with its number and aborts the run with its code.
"$mpirun" -np 1 "$exe" "$good" --output "$work/a" : -np 1 "$exe" "$work/nu.prm" \
  --output "$work/a" >"$work/1.out" 2>"$work/1.err"
code=$?
[ "$code" -eq 1 ]; check $? "an error on process 1 alone: exit 1 (got $code)"
[ "$(count "error on process 1 of 2: Body omega1/Material/$nu" "$work/1.err")" -eq 1 ]
check $? "printed once, naming process 1"

# 2. Every process: one line, no process number.
"$mpirun" -np 2 "$exe" "$work/nu.prm" --output "$work/b" >"$work/2.out" 2>"$work/2.err"
code=$?
[ "$code" -eq 1 ]; check $? "the same error on both processes: exit 1 (got $code)"
[ "$(count "ddcontact: error: Body omega1/Material/$nu" "$work/2.err")" -eq 1 ]
check $? "printed once"
[ "$(count "on process" "$work/2.err")" -eq 0 ]; check $? "without a process number"

# 3. A different error on each process: each once, with its process.
"$mpirun" -np 1 "$exe" "$work/nu.prm" --output "$work/c" : -np 1 "$exe" "$work/E.prm" \
  --output "$work/c" >"$work/3.out" 2>"$work/3.err"
code=$?
[ "$code" -eq 1 ]; check $? "different errors: exit 1 (got $code)"
[ "$(count "error on process 0: Body omega1/Material/$nu" "$work/3.err")" -eq 1 ] &&
  [ "$(count "error on process 1: Body omega1/Material/Young's modulus" "$work/3.err")" -eq 1 ]
check $? "each printed once with its process"

# 4. Parallel/Mesh = distributed where no mesh is split (two bodies on two
# processes, a body each): refused in one line naming the entry.
"$mpirun" -np 2 "$exe" "$good" --set "Parallel/Mesh=distributed" \
  --output "$work/d" >"$work/4.out" 2>"$work/4.err"
code=$?
[ "$code" -eq 1 ]; check $? "Mesh = distributed without process groups: exit 1 (got $code)"
[ "$(count "ddcontact: error: Parallel/Mesh: distributed, but every body is solved whole on one process" "$work/4.err")" -eq 1 ]
check $? "printed once, naming Parallel/Mesh"

# 5. A solver without several processes (SolverCapabilities) under
# mpirun: refused in one line naming the entry and the solvers that can.
"$mpirun" -np 2 "$exe" "$good" --set "Contact solver/Solver=monolithic" \
  --set "Adaptation/Mode=nested" --output "$work/e" >"$work/5.out" 2>"$work/5.err"
code=$?
[ "$code" -eq 1 ]; check $? "the monolithic solver under mpirun: exit 1 (got $code)"
[ "$(count "ddcontact: error: Contact solver/Solver: monolithic runs on one process; use Solver = dd-newton or dd under mpirun" "$work/5.err")" -eq 1 ]
check $? "printed once, naming Contact solver/Solver"
[ ! -e "$work/e/summary.json" ]; check $? "a refused run writes no summary"

for f in "$work"/*.err; do echo "--- $(basename "$f")"; grep "ddcontact" "$f"; done
[ "$failures" -eq 0 ] && echo PASSED || { echo "FAILED ($failures)"; exit 1; }
