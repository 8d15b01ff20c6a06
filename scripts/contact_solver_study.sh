#!/usr/bin/env bash
# Study (not a test): the work of the contact solvers against the penalty c,
# the mesh and the number of bodies. For the paper's scene (fixed meshes),
# prm/three_bodies.prm and prm/hertz.prm (penalty alone, no augmented
# Lagrangian), c = 1e-8 ... 10 and two refinements (h and h/8), it runs
#   dd-newton   the semismooth Newton method on the contact pressure,
#   dd          the paper's DD with Anderson acceleration,
#   monolithic  the semismooth Newton method on (16) (reference force),
# all to Tolerance = 1e-8, and writes doc/contact-solvers.csv:
# body-solve sets (one solve of every body: a "DD iteration"), the
# preconditioner's solve sets, Newton steps, CG iterations, the contact
# force (summed over the pairs), the contact-solve wall time and the exit
# code (4: stopped with a message; dd-newton gives up after 40 Newton steps,
# the DD after 2000 iterations, every run after 120 s, exit 124).
# scripts/contact_solver_table.py turns it into the table of
# doc/contact-solvers.md section 3.
#
#   scripts/contact_solver_study.sh [EXECUTABLE]   (default build-release/ddcontact)
set -uo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build-release/ddcontact}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
csv=doc/contact-solvers.csv
echo "scene,c,refinement,solver,exit,body_solve_sets,preconditioner_solve_sets,newton_steps,krylov_iterations,force,contact_solve_s" > "$csv"

# The meshes of refinement r of each scene (h / 2^r), into the array mesh_args.
mesh() { # scene r
  mesh_args=()
  local b
  case $1 in
    paper) mesh_args=(--set "Body omega1/Mesh/Initial refinement=$((1 + $2))"
                      --set "Body omega2/Mesh/Initial refinement=$2") ;;
    three_bodies) for b in punch plate base; do
                    mesh_args+=(--set "Body $b/Mesh/Initial refinement=$((1 + $2))"); done ;;
    hertz) for b in upper lower; do
             mesh_args+=(--set "Body $b/Mesh/Box refinement=$((4 + $2))"); done ;;
  esac
}
prm() { case $1 in paper) echo prm/paper_two_bodies.prm ;; *) echo prm/$1.prm ;; esac; }
pairs() { case $1 in three_bodies) echo punch_on_plate plate_on_base ;; *) echo S ;; esac; }

run() { # scene c r solver
  local scene=$1 c=$2 r=$3 solver=$4 args=() p
  for p in $(pairs "$scene"); do args+=(--set "Contact pair $p/Penalty=$c"); done
  case $solver in
    dd) args+=(--set "Contact solver/Solver=dd" --set "Contact solver/Domain decomposition/Relaxation=anderson") ;;
    *) args+=(--set "Contact solver/Solver=$solver") ;;
  esac
  rm -rf "$out/r"
  mesh "$scene" "$r"
  timeout 120 "$exe" "$(prm "$scene")" --output "$out/r" \
    --set "Adaptation/Mode=none" --set "Output/Write vtu=false" \
    --set "Contact solver/Tolerance=1e-8" \
    --set "Contact pair S/Formulation=penalty" \
    --set "Contact solver/DD-Newton/Max Newton iterations=40" \
    --set "Contact solver/Monolithic/Max Newton iterations=40" \
    --set "Contact solver/Max iterations=2000" \
    "${mesh_args[@]}" "${args[@]}" > "$out/log" 2>&1
  local code=$?
  python3 - "$out/r/summary.json" "$scene,$c,$r,$solver,$code" >> "$csv" <<'EOF'
import json, math, sys
try:
    d = json.load(open(sys.argv[1]))
except Exception:
    d = {}
force = sum(math.hypot(*c["force"][0]) for c in d.get("contact", [])) \
    if d else ""
fields = [d.get(k, "") for k in ("body_solve_sets", "preconditioner_solve_sets",
                                 "newton_steps", "krylov_iterations")]
if d.get("contact_solver") == "dd":
    fields[0] = d.get("dd_iterations", "")
t = d.get("timings", {}).get("contact solve", "")
print(",".join([sys.argv[2]] + [str(x) for x in fields] +
               ["%.10g" % force if force != "" else "", str(t)]))
EOF
  tail -n 1 "$csv"
}

for scene in paper three_bodies hertz; do
  for c in 1e-8 1e-6 1e-4 1e-2 1 10; do
    for r in 0 3; do
      for solver in dd-newton dd monolithic; do
        run "$scene" "$c" "$r" "$solver"
      done
    done
  done
done
