#!/usr/bin/env bash
# Benchmark (not a test): cost of the BEM reference solution (assembly, LU,
# interior stresses at all cell quadrature points) against the FEM setup,
# factorization and solve of the same body, Omega_2 = (-2,2) x (0,1) with
# 1e3 ... 1e5 cells. Needs a Release build directory (default build/;
# BUILD_DIR=... to use another one). Writes doc/bem-cost.csv; doc/bem.md
# quotes it.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
ninja -C "$build" bench_bem_cost
"$build/benchmarks/bench_bem_cost" doc/bem-cost.csv "$@"
cat doc/bem-cost.csv
