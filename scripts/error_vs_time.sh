#!/usr/bin/env bash
# Benchmark (not a test): error against run time on the paper's scene
# (prm/paper_two_bodies.prm) for the solution strategies of the code --
# uniform refinement with the DD and with the monolithic Newton solver,
# Kelly-adaptive DD, the combined algorithm (Fig. 2) with the printed
# estimator (27) and with its scale-consistent form, fixed gamma against
# Anderson relaxation, plain penalty against the augmented Lagrangian.
# doc/error-vs-time.md discusses the results.
#
#   scripts/error_vs_time.sh               full benchmark (~10 min): builds
#       build/ddcontact (Release), runs every series into
#       build/error-vs-time/runs, writes doc/error-vs-time.csv and the plots
#       doc/error-vs-time/*.png (Debian's /usr/bin/python3 with matplotlib)
#   scripts/error_vs_time.sh --reference   (re)computes the reference
#       doc/error-vs-time-reference.json and -profile.csv (~5 min; runs that
#       exist in build/error-vs-time/reference are reused)
#   scripts/error_vs_time.sh --quick       smoke test: one coarse run per
#       strategy, a few seconds, no plots, plain python3; exit status 1 if a
#       run fails or an error is not finite
# Also prm/hertz.prm against the closed form of doc/verification.md §2.2.
# Options: --exe PATH (no build), --out DIR (runs and, in quick mode, the
# CSV go there), --no-plot.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

quick=0; reference=0; plot=1; exe=""; out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --reference) reference=1 ;;
    --no-plot) plot=0 ;;
    --exe) exe="$2"; shift ;;
    --out) out="$2"; shift ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "error_vs_time.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

if [ -z "$exe" ]; then
  exe="$root/build/ddcontact"
  if [ "$quick" = 0 ]; then
    cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null || exit 1
    ninja -j1 -C "$root/build" ddcontact || exit 1
  fi
fi
[ -x "$exe" ] || { echo "error_vs_time.sh: no executable '$exe'" >&2; exit 1; }

# Quick mode needs only the standard library; the full mode draws plots
# with Debian's python (a python earlier in PATH may lack matplotlib).
if [ "$quick" = 1 ]; then PY=python3; else PY=/usr/bin/python3; fi
eval_py="$root/scripts/error_vs_time_eval.py"
scene="$root/prm/paper_two_bodies.prm"
ref_json="$root/doc/error-vs-time-reference.json"
ref_profile="$root/doc/error-vs-time-reference-profile.csv"
if [ -z "$out" ]; then
  if [ "$quick" = 1 ]; then out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
  else out="$root/build/error-vs-time"; fi
fi
mkdir -p "$out"

common=(--set "Output/Write vtu=false" --set "Adaptation/Write every mesh=false")
# Exact contact: dd-newton with nodal multipliers (the Uzawa loop of the DD
# stops at about 1e-3 of the approach on these non-matching meshes).
AL=(--set "Domain decomposition/Augmented Lagrangian=true" --set "Domain decomposition/Solver=dd-newton")
relax() { echo "Domain decomposition/Relaxation=$1"; }

# ------------------------------------------------------------ reference
if [ "$reference" = 1 ]; then
  refruns="$out/reference"; mkdir -p "$refruns"
  # Monolithic Newton (a route independent of the DD) on uniform degree-2
  # meshes of both bodies (P2 triangles above, Q2 below): the penalised
  # problem of the scene (c = 0.05) on levels 3, 4, 5 (h = 1/32 .. 1/128),
  # and c = 0.025, 0.0125 on levels 2, 3, 4 for the limit c -> 0 (exact
  # contact).
  for cr in 0.05:3 0.05:4 0.025:2 0.025:3 0.025:4 0.0125:2 0.0125:3 0.0125:4 0.05:5; do
    c=${cr%:*}; r=${cr#*:}; name="p2_c${c}_r$r"
    [ -f "$refruns/$name/summary.json" ] && continue
    echo "== $name"
    "$exe" "$scene" --output "$refruns/$name" "${common[@]}" \
      --set "Adaptation/Mode=none" --set "Domain decomposition/Solver=monolithic" \
      --set "Contact pair S/Penalty=$c" \
      --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2" \
      --set "Body omega1/Mesh/Initial refinement=$r" --set "Body omega2/Mesh/Initial refinement=$r" \
      > "$refruns/$name.log" 2>&1 || { echo "reference run $name failed" >&2; exit 1; }
  done
  $PY "$eval_py" reference "$refruns" "$ref_json" "$ref_profile" || exit 1
  exit 0
fi
[ -f "$ref_json" ] || { echo "error_vs_time.sh: no reference $ref_json (run with --reference)" >&2; exit 1; }

runs="$out/runs"; rm -rf "$runs"; mkdir -p "$runs"
manifest="$out/manifest.txt"; : > "$manifest"
failed=0
echo "machine load before: $(uptime)" | tee "$out/load.txt"

# run NAME SERIES PROBLEM DEG1 DEG2 SETTING [--set ...]: one run of the
# paper's scene; PROBLEM is the reference it is measured against (penalty:
# the penalised problem of the scene; exact: exact contact).
run() {
  local name=$1 series=$2 problem=$3 d1=$4 d2=$5 setting=$6
  shift 6
  echo "$name|$series|$problem|$d1|$d2|$setting" >> "$manifest"
  if ! "$exe" "${run_scene:-$scene}" --output "$runs/$name" "${common[@]}" "$@" > "$runs/$name.log" 2>&1; then
    echo "FAILED: $name (exit status $?, see $runs/$name.log)" >&2; failed=1
  fi
  [ "$quick" = 1 ] || grep -E "^wall time" "$runs/$name.log" | sed "s/^/  $name: /"
}
# Both bodies at refinement level r (array LV); Omega_1 alone (O1A, O4A).
lv() { LV=(--set "Body omega1/Mesh/Initial refinement=$1" --set "Body omega2/Mesh/Initial refinement=$1"); }

if [ "$quick" = 1 ]; then
  U_MONO="0"; U_P2="0"; U_DD="0"; U_FIXED="0"; U_AUTO="0"; U_AL="0"
  K_CYC="1"; K_CYC_FIXED="1"; K_CYC_AL="1"; K_CYC_FINE=""; P_CAP="100"; P_CAP_FIXED="100"
  S_DELTA="0.1"; S_DELTA_FIXED="0.1"; S_DELTA_FINE=""; O1=0
else
  U_MONO="0 1 2 3 4 5"; U_P2="0 1 2 3"; U_DD="0 1 2 3 4 5"; U_FIXED="0 1 2 3 4"
  U_AUTO="0 1 2 3 4"; U_AL="0 1 2 3 4 5"
  K_CYC="2 4 6 8 10 12"; K_CYC_FIXED="2 4 6 8"; K_CYC_AL="2 4 6 8"; K_CYC_FINE="6 8 10 12 14"
  P_CAP="300 1200 5000 20000"; P_CAP_FIXED="300 1200 5000"
  S_DELTA="0.2 0.14 0.1 0.07 0.05 0.035 0.025"; S_DELTA_FIXED="0.1 0.07 0.05 0.035"
  S_DELTA_FINE="0.05 0.035 0.025"; O1=2
fi
O1A=(--set "Body omega1/Mesh/Initial refinement=$O1")
O4A=(--set "Body omega1/Mesh/Initial refinement=4")

# Uniform refinement of both bodies (Omega_1 triangles and Omega_2
# quadrilaterals on the same 16 x 4 x 4^r squares), fixed meshes.
none=(--set "Adaptation/Mode=none")
for r in $U_MONO; do lv $r; run "uni-mono-p1-r$r" uniform-monolithic-P1 penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "Domain decomposition/Solver=monolithic"; done
for r in $U_P2; do lv $r; run "uni-mono-p2-r$r" uniform-monolithic-P2 penalty 2 2 "r=$r" "${none[@]}" "${LV[@]}" --set "Domain decomposition/Solver=monolithic" --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2"; done
for r in $U_DD; do lv $r; run "uni-dd-anderson-r$r" uniform-DD-anderson penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "$(relax anderson)"; done
for r in $U_FIXED; do lv $r; run "uni-dd-fixed-r$r" uniform-DD-fixed penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "$(relax fixed)"; done
for r in $U_AUTO; do lv $r; run "uni-dd-auto-r$r" uniform-DD-auto penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "$(relax auto)"; done
for r in $U_AL; do lv $r; run "uni-ddnewton-exact-r$r" uniform-DDnewton-exact exact 1 1 "r=$r" "${none[@]}" "${LV[@]}" "${AL[@]}"; done

# Kelly-adaptive DD of Omega_2 (Omega_1 stays the paper's uniform mesh:
# Kelly is refused on triangles): nested (DD to convergence,
# then refine the 30 % largest) and combined with Doerfler marking (50 %).
kelly_n=(--set "Adaptation/Mode=nested" --set "Adaptation/Estimator=kelly" --set "Adaptation/Marking=fraction" --set "Adaptation/Fraction=0.3")
kelly_c=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=kelly" --set "Adaptation/Marking=doerfler" --set "Adaptation/Fraction=0.5")
for n in $K_CYC; do run "kelly-nested-anderson-c$n" kelly-nested-anderson penalty 1 1 "cycles=$n" "${kelly_n[@]}" "${O1A[@]}" --set "Adaptation/Max cycles=$n" --set "$(relax anderson)"; done
for n in $K_CYC; do run "kelly-combined-anderson-c$n" kelly-combined-doerfler-anderson penalty 1 1 "cycles=$n" "${kelly_c[@]}" "${O1A[@]}" --set "Adaptation/Max cycles=$n" --set "$(relax anderson)"; done
for n in $K_CYC_FIXED; do run "kelly-nested-fixed-c$n" kelly-nested-fixed penalty 1 1 "cycles=$n" "${kelly_n[@]}" "${O1A[@]}" --set "Adaptation/Max cycles=$n" --set "$(relax fixed)"; done
for n in $K_CYC_AL; do run "kelly-nested-ddnewton-exact-c$n" kelly-nested-DDnewton-exact exact 1 1 "cycles=$n" "${kelly_n[@]}" "${O1A[@]}" --set "Adaptation/Max cycles=$n" "${AL[@]}"; done
# The same with Omega_1 one level finer than Omega_2's finest uniform run
# would need: r = 4 (h = 1/64), which lowers the floor Omega_1 sets.
for n in $K_CYC_FINE; do run "kelly-nested-anderson-o4-c$n" kelly-nested-anderson-omega1-r4 penalty 1 1 "cycles=$n" "${kelly_n[@]}" "${O4A[@]}" --set "Adaptation/Max cycles=$n" --set "$(relax anderson)"; done

# The combined algorithm (Fig. 2) with the estimator (27) as printed: it
# marks nearly every cell, so the cell cap decides the mesh.
printed=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=fem-bem" --set "Adaptation/Delta=0.1")
for m in $P_CAP; do run "fembem-printed-anderson-m$m" fembem-printed-anderson penalty 1 1 "max cells=$m" "${printed[@]}" "${O1A[@]}" --set "Adaptation/Max cells=$m" --set "$(relax anderson)"; done
for m in $P_CAP_FIXED; do run "fembem-printed-fixed-m$m" fembem-printed-fixed penalty 1 1 "max cells=$m" "${printed[@]}" "${O1A[@]}" --set "Adaptation/Max cells=$m" --set "$(relax fixed)"; done

# The combined algorithm with the scale-consistent estimator for a range
# of delta, with the paper's gamma = 0.02 and with Anderson.
scaled=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=fem-bem-scaled" --set "Adaptation/Marking=threshold")
for d in $S_DELTA; do run "fembem-scaled-anderson-d$d" fembem-scaled-anderson penalty 1 1 "delta=$d" "${scaled[@]}" "${O1A[@]}" --set "Adaptation/Delta=$d" --set "$(relax anderson)"; done
for d in $S_DELTA_FIXED; do run "fembem-scaled-fixed-d$d" fembem-scaled-fixed penalty 1 1 "delta=$d" "${scaled[@]}" "${O1A[@]}" --set "Adaptation/Delta=$d" --set "$(relax fixed)"; done
for d in $S_DELTA_FINE; do run "fembem-scaled-anderson-o4-d$d" fembem-scaled-anderson-omega1-r4 penalty 1 1 "delta=$d" "${scaled[@]}" "${O4A[@]}" --set "Adaptation/Delta=$d" --set "$(relax anderson)"; done

# Hertz (prm/hertz.prm): two large blocks, refined toward the contact
# (Box refinement b), measured against the closed form at the computed
# force (doc/verification.md §2.2): peak pressure, half-width (least-squares
# fit of p^2 against x1^2) and the pressure profile. Exact contact (the scene's augmented
# Lagrangian) and plain penalty, both with Anderson.
if [ "$quick" = 1 ]; then H_BOX="3"; else H_BOX="3 4 5 6 7 8"; fi
run_scene="$root/prm/hertz.prm"
for b in $H_BOX; do run "hertz-exact-b$b" hertz-DD-newton-exact hertz 1 1 "box refinement=$b" --set "Body upper/Mesh/Box refinement=$b" --set "Body lower/Mesh/Box refinement=$b"; done
for b in $H_BOX; do run "hertz-penalty-b$b" hertz-DD-anderson-penalty hertz 1 1 "box refinement=$b" --set "Domain decomposition/Solver=dd" --set "Domain decomposition/Relaxation=anderson" --set "Body upper/Mesh/Box refinement=$b" --set "Body lower/Mesh/Box refinement=$b" --set "Domain decomposition/Augmented Lagrangian=false"; done
unset run_scene

echo "machine load after: $(uptime)" | tee -a "$out/load.txt"

# The floor: one factorization + one solve of a single body without contact
# (prm/benchmark/single_body.prm), per element type, against dofs.
if [ "$quick" = 1 ]; then F_Q1="0"; F_Q2="0"; F_P1="0"; F_P2="0"
else F_Q1="0 1 2 3 4 5 6"; F_Q2="0 1 2 3 4"; F_P1="0 1 2 3 4 5"; F_P2="0 1 2 3"; fi
floor_run() { # celltype degree level
  local name="floor_$1_p$2_r$3"
  "$exe" "$root/prm/benchmark/single_body.prm" --output "$runs/$name" \
    --set "Body block/Element/Cell type=$1" --set "Body block/Element/Degree=$2" \
    --set "Body block/Mesh/Initial refinement=$3" > "$runs/$name.log" 2>&1 \
    || { echo "FAILED: $name" >&2; failed=1; }
}
for r in $F_Q1; do floor_run quadrilateral 1 $r; done
for r in $F_Q2; do floor_run quadrilateral 2 $r; done
for r in $F_P1; do floor_run triangle 1 $r; done
for r in $F_P2; do floor_run triangle 2 $r; done
floor_csv="$out/floor.csv"
$PY "$eval_py" floor "$runs" "$floor_csv" || failed=1

if [ "$quick" = 1 ]; then csv="$out/error-vs-time.csv"; else csv="$root/doc/error-vs-time.csv"; fi
$PY "$eval_py" evaluate "$manifest" "$runs" "$ref_json" "$ref_profile" "$floor_csv" "$csv" || failed=1
if [ "$quick" = 0 ]; then
  cp "$floor_csv" "$root/doc/error-vs-time-floor.csv"
  cp "$out/load.txt" "$root/doc/error-vs-time-load.txt"
  if [ "$plot" = 1 ]; then
    $PY "$root/scripts/plot_error_vs_time.py" "$csv" "$ref_json" "$root/doc/error-vs-time" || failed=1
  fi
fi
[ "$failed" = 0 ] && echo "error_vs_time: all runs finished, all errors finite"
exit $failed
