#!/usr/bin/env bash
# Study (not a test): reproduces the paper's figures 4, 7, 8, 9 and 10 with
# the combined algorithm (Fig. 2) on the paper's scene. Builds the Release
# executable, runs the sweeps into doc/paper-reproduction/runs (not kept in
# git), and draws the figures with scripts/plot_paper_figures.py into
# doc/paper-reproduction/. doc/paper-reproduction.md discusses them.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install_deps.sh
# Debian's python, where Debian's matplotlib lives (a python earlier in PATH,
# e.g. from pyenv, would not see it).
PY=/usr/bin/python3
if ! $PY -c "import matplotlib" 2>/dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends python3-matplotlib python3-numpy
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
ninja -C build ddcontact
# SKIP_RUNS=1: plots only, from the runs if they are still there, otherwise
# figures 8 and 10 from doc/paper-reproduction/delta_sweep.csv.
if [ "${SKIP_RUNS:-0}" = 1 ]; then
  if [ -d doc/paper-reproduction/runs ]; then
    $PY scripts/plot_paper_figures.py doc/paper-reproduction/runs doc/paper-reproduction
  else
    $PY scripts/plot_paper_figures.py --from-csv doc/paper-reproduction
  fi
  exit
fi

exe=build/ddcontact
runs=doc/paper-reproduction/runs
rm -rf "$runs"; mkdir -p "$runs"
scene=prm/paper_two_bodies.prm

run() { # name, then --set overrides
  local name="$1"; shift
  echo "== $name"
  "$exe" "$scene" --output "$runs/$name" "$@" > "$runs/$name.log"
  grep -E "point omega2|contact S:|wall time" "$runs/$name.log" | sed 's/^/   /'
}

# Reference: the fixed-mesh DD with Omega_2 uniform and fine (h = 1/128,
# finer than any adapted cell but those at the level cap) and Omega_1 as in
# the adaptive runs (the limit the adaptation of Omega_2 alone approaches),
# residual test; its pressure is the reference line of Fig. 9 and its
# u(0.5, 0.75) the converged value of Fig. 8.
run reference --set "Adaptation/Mode=none" --set "Body omega2/Mesh/Initial refinement=5" \
  --set "Contact solver/Domain decomposition/Relaxation=anderson" --set "Contact solver/Tolerance=1e-9" \
  --set "Output/Write vtu=false"

# Fig. 8 and 10: the combined algorithm for a range of thresholds delta.
for delta in 0.2 0.14 0.1 0.07 0.05 0.035 0.025; do
  run "delta_$delta" --set "Adaptation/Delta=$delta" --set "Adaptation/Write every mesh=false" \
    --set "Contact solver/Domain decomposition/Relaxation=anderson" --set "Output/Write vtu=false"
done

# Fig. 4, 7 and 9: the paper's settings at delta = 0.1 -- fixed gamma = 0.02,
# the paper's increment test eps_u = 0.0015 -- with the contact profiles of
# every iteration and the mesh of every adaptation step.
run paper_delta_0.1 --set "Adaptation/Delta=0.1" --set "Contact solver/Domain decomposition/Stopping test=paper" \
  --set "Contact solver/Write every iteration=true"
# The same to the residual test (the converged answer on the same meshes).
run paper_delta_0.1_residual --set "Adaptation/Delta=0.1" --set "Output/Write vtu=false"

# The estimator exactly as printed, (27), at the paper's delta = 0.1: it
# marks (nearly) every cell; the cell cap stops it.
run printed_delta_0.1 --set "Adaptation/Estimator=fem-bem" --set "Adaptation/Delta=0.1" \
  --set "Adaptation/Max cells=20000" --set "Contact solver/Domain decomposition/Relaxation=anderson" \
  --set "Output/Write vtu=false" --set "Adaptation/Write every mesh=false"

$PY scripts/plot_paper_figures.py "$runs" doc/paper-reproduction
