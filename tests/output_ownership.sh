#!/usr/bin/env bash
# DESCRIPTION: a run owns only what it wrote (doc/reliability.md): files of
# other programs in its output directory are never removed or changed; a
# name the run would write that is not its own refuses the run, which then
# changes nothing; the input file is never overwritten; a refused rerun
# leaves the earlier results exactly as they were; a rerun removes the
# earlier run's own files only, and none that changed since; a stale or
# empty lock is taken over in one line; an error found after the first
# solve leaves a true summary.json, never "running"
# usage: output_ownership.sh DDCONTACT_EXECUTABLE SOURCE_DIR
set -u
source "$(dirname "$0")/record_checks.sh"
exe="$1"; src="$2"
scene="$src/prm/friction_patch.prm"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
# The state of a directory: every file (hidden ones too) with its checksum.
snapshot() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 -r sha256sum); }
run() { # run DIR ARGS...: the scene into DIR; stdout, stderr in $work/last.*
  local dir="$1"; shift
  "$exe" --output "$dir" "$scene" "$@" >"$work/last.out" 2>"$work/last.err"
}
foreign_files() { # files of "another program" in DIR
  mkdir -p "$1"
  echo '<VTKFile type="UnstructuredGrid"/>' >"$1/mesh.vtu"
  echo '<VTKFile type="Collection"/>' >"$1/series.pvd"
  printf 'a,b\n1,2\n' >"$1/contact_list.csv"
  printf 'notes of another program\n' >"$1/notes.txt"
}

# 1. Another program's files whose names the run would write
# (summary.json, history.csv): refused in one line, nothing changes.
d="$work/foreign"
foreign_files "$d"
echo '{"producer": "another program"}' >"$d/summary.json"
printf 'k,value\n' >"$d/history.csv"
before=$(snapshot "$d")
run "$d"; code=$?
[ $code -eq 1 ] && [ "$(wc -l <"$work/last.err")" -eq 1 ] &&
  grep -q "Output directory: .*summary.json" "$work/last.err"
check $? "names the run would write refuse it in one line (exit $code: $(head -1 "$work/last.err"))"
[ "$(snapshot "$d")" = "$before" ]; check $? "... and the refused run changed nothing"

# 2. Without those two: the run uses the directory, says so in one line,
# and leaves the other program's files as they were.
rm "$d/summary.json" "$d/history.csv"
before=$(snapshot "$d")
run "$d"; code=$?
[ $code -eq 0 ]; check $? "a directory with other files is used (exit $code)"
[ "$(grep -c "file(s) there that this run did not write are left" "$work/last.out")" -eq 1 ]
check $? "... with one line that says so"
[ "$(status_of "$d/summary.json")" = "converged" ]; check $? "... and converges"
echo "$before" >"$work/before"; snapshot "$d" >"$work/after"
[ -z "$(comm -23 <(sort "$work/before") <(sort "$work/after"))" ]; check $? "... every foreign file is unchanged"
# A rerun removes only what the first wrote.
run "$d"; code=$?
snapshot "$d" >"$work/after"
[ $code -eq 0 ] && [ -z "$(comm -23 <(sort "$work/before") <(sort "$work/after"))" ]
check $? "a rerun leaves the foreign files too (exit $code)"

# 3. The input file in the output directory, under the dump's name: never
# overwritten; the parameters used go to parameters.used.prm.
d="$work/input"
mkdir -p "$d"; cp "$scene" "$d/parameters.prm"
sum=$(sha256sum <"$d/parameters.prm")
"$exe" --output "$d" "$d/parameters.prm" >"$work/last.out" 2>"$work/last.err"; code=$?
[ $code -eq 0 ] && [ "$(sha256sum <"$d/parameters.prm")" = "$sum" ] && [ -s "$d/parameters.used.prm" ]
check $? "the input file is not overwritten (exit $code)"
"$exe" --output "$d" "$d/parameters.prm" >"$work/last.out" 2>"$work/last.err"; code=$?
[ $code -eq 0 ] && [ "$(sha256sum <"$d/parameters.prm")" = "$sum" ]
check $? "... nor by a rerun (exit $code)"

# 4. A refused rerun (errors found in the setup: a friction coefficient
# < 0 only between the first contact points, a misspelled mesh file)
# leaves the earlier results exactly as they were.
d="$work/rerun"
run "$d" >/dev/null; code=$?
[ $code -eq 0 ]; check $? "a first run (exit $code)"
before=$(snapshot "$d")
run "$d" --set "Contact pair S/Friction coefficient=if(abs(x-0.4031)<0.01, -0.1, 0.2)"; code=$?
[ $code -eq 1 ] && [ "$(wc -l <"$work/last.err")" -eq 1 ] && grep -q "Friction coefficient" "$work/last.err"
check $? "a coefficient < 0 between the contact points is refused before the solve (exit $code: $(head -1 "$work/last.err"))"
[ "$(snapshot "$d")" = "$before" ]; check $? "... and the earlier results are untouched"
run "$d" --set "Body omega1/Mesh/Type=file" --set "Body omega1/Mesh/File=nothere.msh"; code=$?
[ $code -eq 1 ] && [ "$(snapshot "$d")" = "$before" ]
check $? "a misspelled mesh file leaves them untouched too (exit $code)"
[ "$(status_of "$d/summary.json")" = "converged" ]; check $? "... summary.json still says converged"
run "$work/never" --set "Body omega1/Material/Young's modulus=-1"; code=$?
[ $code -eq 1 ] && [ ! -e "$work/never" ]; check $? "a refused run does not even make its directory"

touch "$work/a_file"
run "$work/a_file"; code=$?
[ $code -eq 1 ] && grep -q "is a file, not a directory" "$work/last.err" && [ ! -s "$work/a_file" ]
check $? "--output naming a file is refused in one line (exit $code)"

# 5. A file of the earlier run changed since is no longer the run's: it
# is kept, and as the run would write it, the run is refused.
echo "# my note" >>"$d/history.csv"
before=$(snapshot "$d")
run "$d"; code=$?
[ $code -eq 1 ] && grep -q "history.csv" "$work/last.err" && [ "$(snapshot "$d")" = "$before" ]
check $? "a result changed since it was written is kept, the run refused (exit $code)"
rm "$d/history.csv"

# 6. A lock that names a process that no longer runs, or none, is taken
# over with one line.
echo 99999999 >"$d/.ddcontact.lock"
run "$d"; code=$?
[ $code -eq 0 ] && [ "$(grep -c "took over the lock" "$work/last.out")" -eq 1 ]
check $? "a stale lock is taken over (exit $code)"
: >"$d/.ddcontact.lock"
run "$d"; code=$?
[ $code -eq 0 ] && [ "$(grep -c "took over the lock" "$work/last.out")" -eq 1 ] && [ ! -e "$d/.ddcontact.lock" ]
check $? "an empty lock is taken over (exit $code)"

# 7. An error met only after a refinement (a traction not finite in a
# band that only the refined mesh's points reach): the first solve's
# results stay, and summary.json names the error and the last completed
# step, never "running".
d="$work/late"
run "$d" --set "Adaptation/Mode=uniform" --set "Adaptation/Bodies=omega1" \
  --set "Adaptation/Max cycles=2" \
  --set "Body omega1/Boundary conditions/Neumann=0: 3/7*P; -S | 1: -3/7*P; if(abs(y-1.4)<0.005, 1/0, S)"
code=$?
[ $code -eq 1 ] && [ "$(wc -l <"$work/last.err")" -eq 1 ] && [ "$(status_of "$d/summary.json")" = "bad_input" ] &&
  python3 -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(not ('Neumann' in s['error'] and s['last_completed_step'].startswith('adaptation cycle 0')))" "$d/summary.json" &&
  [ -f "$d/bodies-0000.pvtu" ] && [ -f "$d/omega1-0000.vtu" ]
check $? "an error after a refinement keeps the first solve and names both in summary.json (exit $code)"
run "$work/late2" --set "Loading/Steps=2" \
  --set "Body omega1/Boundary conditions/Dirichlet=3: xy: U; -Delta/(2-2*t)"; code=$?
[ $code -eq 1 ] && [ ! -e "$work/late2" ]
check $? "a load not finite in a later load step is refused before the run (exit $code: $(head -1 "$work/last.err"))"

if [ $failures -gt 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all checks passed"
