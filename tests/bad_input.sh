#!/usr/bin/env bash
# DESCRIPTION: bad input gets one line naming the parameter or file and a non-zero exit, never a crash
# usage: bad_input.sh DDCONTACT_EXECUTABLE SOURCE_DIR
set -u
exe="$1"; src="$2"
base="$src/prm/two_bodies.prm"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failures=0

# judge NAME EXPECTED_SUBSTRING EXIT_CODE: the run that wrote
# $work/stderr must have failed cleanly with one line of ddcontact's
# (mpirun adds its own report of the exit code after it).
judge_() {
  local name="$1" expect="$2" code="$3" lines
  lines=$(grep -c "^ddcontact: error" "$work/stderr")
  if [ "$code" -eq 0 ] || [ "$code" -ge 128 ] || [ "$lines" -ne 1 ] ||
     grep -q -E "Stacktrace|Aborted|Signal|Segmentation" "$work/stderr" ||
     ! grep -q -F -- "$expect" "$work/stderr"; then
    echo "FAIL $name: exit $code, $lines error line(s) on stderr, expected '$expect':"
    sed 's/^/    /' "$work/stderr" | head -5
    failures=$((failures + 1))
  else
    echo "ok   $name: $(grep "^ddcontact: error" "$work/stderr")"
  fi
}

# case NAME EXPECTED_SUBSTRING ARGS...: one process, and stderr holds
# nothing but that one line.
case_() {
  local name="$1" expect="$2"; shift 2
  "$exe" --output "$work/out" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  if [ "$(wc -l <"$work/stderr")" -ne 1 ]; then
    echo "FAIL $name: $(wc -l <"$work/stderr") lines on stderr, expected one:"
    sed 's/^/    /' "$work/stderr" | head -5
    failures=$((failures + 1))
    return
  fi
  judge_ "$name" "$expect" $code
}

# mpi_case NAME EXPECTED_SUBSTRING ARGS...: under mpirun, 2 processes.
mpi_case_() {
  local name="$1" expect="$2"; shift 2
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    OMPI_MCA_rmaps_base_oversubscribe=1 DEAL_II_NUM_THREADS=1 \
    mpirun -np 2 "$exe" --output "$work/out" "$@" >"$work/stdout" 2>"$work/stderr"
  judge_ "$name" "$expect" $?
}

case_ "missing parameter file" "no_such.prm" "$work/no_such.prm"
printf 'set Bodies = a\nset Nonsense entry = 3\n' >"$work/unknown.prm"
case_ "unknown entry" "Nonsense entry" "$work/unknown.prm"
case_ "missing mesh file" "nothere.msh" "$base" --set "Body lower/Mesh/Type=file" --set "Body lower/Mesh/File=nothere.msh"
case_ "E <= 0" "Young's modulus" "$base" --set "Body lower/Material/Young's modulus=-1"
case_ "E = 0" "Young's modulus" "$base" --set "Body lower/Material/Young's modulus=0"
case_ "nu = 0.5" "Poisson's ratio" "$base" --set "Body upper/Material/Poisson's ratio=0.5"
case_ "nu = -1.2" "Poisson's ratio" "$base" --set "Body upper/Material/Poisson's ratio=-1.2"
case_ "boundary id not in mesh" "boundary id 7" "$base" --set "Body lower/Boundary conditions/Neumann=7: 0; 1"
case_ "no Dirichlet part" "Body upper/Dirichlet" "$base" --set "Body upper/Boundary conditions/Dirichlet="
case_ "expression does not parse" "Body lower/Neumann" "$base" --set "Body lower/Boundary conditions/Neumann=3: 0; -p*("
case_ "unknown variable" "Body upper/Body force" "$base" --set "Body upper/Boundary conditions/Body force=0; -z"
case_ "--set of an undeclared entry" "No such entry" "$base" --set "Body lower/No such entry=1"
case_ "report point outside its body" "Output/Points" "$base" --set "Output/Points=lower: 9, 9"
case_ "contact pair with unknown body" "Contact pair S" "$src/prm/paper_two_bodies.prm" --set "Contact pair S/Body 2=nobody"
case_ "gamma outside (0, 1]" "Gamma" "$src/prm/paper_two_bodies.prm" --set "Domain decomposition/Gamma=0"
case_ "combined with the monolithic solver" "Adaptation/Mode" "$src/prm/paper_two_bodies.prm" --set "Domain decomposition/Solver=monolithic"
case_ "body owner names no body" "Parallel/Body owners" "$base" --set "Parallel/Body owners=lower: 0, nobody: 0"
case_ "body owner on a missing process" "does not exist" "$base" --set "Parallel/Body owners=lower: 0, upper: 3"
case_ "body without owner" "'upper' is not listed" "$base" --set "Parallel/Body owners=lower: 0"
case_ "body owner range backwards" "is not a process or a range" "$base" --set "Parallel/Body owners=lower: 0, upper: 0-0-0"
case_ "body owner range beyond the run" "does not exist" "$base" --set "Parallel/Body owners=lower: 0-1, upper: 0"

mpi_case_ "distributed mesh for a body on one process" "Parallel/Mesh" "$base" --set "Parallel/Mesh=distributed"

total=$(grep -c -E '^(mpi_)?case_ ' "$0")
echo "$((total - failures)) passed, $failures failed"
[ $failures -eq 0 ]
