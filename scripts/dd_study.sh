#!/usr/bin/env bash
# Study (not a test): iterations and wall time of the DD on the paper's scene
# for each relaxation, and the speed-up from solving the bodies concurrently.
# Needs the Release build (scripts/run_main_scene.sh builds build/ddcontact;
# another executable as the first argument). Writes
# doc/dd-study.csv; doc/contact-dd.md quotes it.
set -euo pipefail
cd "$(dirname "$0")/.."
exe=$(realpath "${1:-build/ddcontact}")
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
csv=doc/dd-study.csv
echo "refinement,relaxation,threads,dd_iterations,contact_solve_s,u1,u2,max_pressure" > "$csv"

value() { python3 -c "import json,sys; d=json.load(open('$1')); print($2)"; }

run() { # refinement relaxation threads
  "$exe" prm/paper_two_bodies.prm --output "$out/r" \
    --set "Body omega1/Mesh/Initial refinement=$1" --set "Body omega2/Mesh/Initial refinement=$1" \
    --set "Contact solver/Domain decomposition/Relaxation=$2" --set "Threads=$3" \
    --set "Adaptation/Mode=none" --set "Output/Write vtu=false" > "$out/log"
  s="$out/r/summary.json"
  echo "$1,$2,$3,$(value $s "d['dd_iterations']"),$(value $s "d['timings']['contact solve']"),$(value $s "d['points'][0]['u'][0]"),$(value $s "d['points'][0]['u'][1]"),$(value $s "d['contact'][0]['max_pressure']")" | tee -a "$csv"
}

for relaxation in fixed auto aitken anderson; do run 2 "$relaxation" 2; done
for threads in 1 2; do run 4 anderson "$threads"; run 4 fixed "$threads"; done
