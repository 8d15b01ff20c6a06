#!/usr/bin/env bash
# Benchmark (not a test): error against run time on the paper's scene
# (prm/paper_two_bodies.prm) for the solution strategies of the code --
# uniform refinement with the DD and with the monolithic Newton solver,
# Kelly-adaptive DD, the combined algorithm (Fig. 2) with the printed
# estimator (27) and with its scale-consistent form, fixed gamma against
# Anderson relaxation, plain penalty against the augmented Lagrangian.
# Every adaptive run adapts both bodies, with degree 1 and 2.
# doc/error-vs-time.md discusses the results.
#
#   scripts/error_vs_time.sh               full benchmark (~10 min): builds
#       build/ddcontact (Release), runs every series into
#       build/error-vs-time/runs, writes doc/error-vs-time.csv and the plots
#       doc/error-vs-time/*.png (Debian's /usr/bin/python3 with matplotlib)
#   scripts/error_vs_time.sh --reference   (re)computes the reference
#       doc/error-vs-time-reference.json and -profile.csv (~10 min; runs that
#       exist in build/error-vs-time/reference are reused)
#   scripts/error_vs_time.sh --energy-reference   only the energy reference
#       (adaptive degree 2, ~4 min), written into the existing JSON
#   scripts/error_vs_time.sh --quick       smoke test: one coarse run per
#       strategy, a few seconds, no plots, plain python3; exit status 1 if a
#       run fails or an error is not finite
# Also prm/hertz.prm against the closed form of doc/verification.md §2.2.
# Options: --exe PATH (no build), --out DIR (runs and, in quick mode, the
# CSV go there), --no-plot, --repeat N (timings per run, median; default 3,
# 1 in quick mode; runs over 30 s are timed once), --resume (keep the runs
# of an interrupted sweep and skip those that finished), --part PROBLEM
# (rerun only the series measured against PROBLEM -- penalty, exact or
# hertz -- and replace their rows of doc/error-vs-time.csv; the floor is
# taken from doc/error-vs-time-floor.csv).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

quick=0; reference=0; energy_reference=0; plot=1; exe=""; out=""; repeat=""; resume=0; part=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --reference) reference=1 ;;
    --energy-reference) energy_reference=1 ;;
    --repeat) repeat="$2"; shift ;;
    --resume) resume=1 ;;
    --part) part="$2"; shift ;;
    --no-plot) plot=0 ;;
    --exe) exe="$2"; shift ;;
    --out) out="$2"; shift ;;
    -h|--help) sed -n '2,31p' "$0"; exit 0 ;;
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
AL=(--set "Contact pair S/Formulation=exact" --set "Contact solver/Solver=dd-newton")
relax() { echo "Contact solver/Domain decomposition/Relaxation=$1"; }

# ------------------------------------------------------------ reference
# The energy reference: monolithic Newton on the meshes of nested FEM-BEM
# adaptation of both bodies with degree 2 (Doerfler 0.5), Max cycles 8 ..
# 16 (31 k .. 426 k dofs); F(N) converges geometrically along the sequence
# (F - F_h ~ N^-2), so Aitken's extrapolation of the last three values is the
# limit, and the spread of the last three extrapolations its uncertainty.
energy_reference_runs() {
  for n in 8 9 10 11 12 13 14 15 16; do
    name="p2_adaptive_c$n"
    [ -f "$refruns/$name/summary.json" ] && continue
    echo "== $name"
    "$exe" "$scene" --output "$refruns/$name" "${common[@]}" \
      --set "Adaptation/Mode=nested" --set "Adaptation/Estimator=fem-bem-scaled" \
      --set "Adaptation/Marking=doerfler" --set "Adaptation/Fraction=0.5" \
      --set "Adaptation/Bodies=omega1, omega2" --set "Adaptation/Max level=12" \
      --set "Adaptation/Max cycles=$n" --set "Contact solver/Solver=monolithic" \
      --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2" \
      > "$refruns/$name.log" 2>&1 || { echo "reference run $name failed" >&2; exit 1; }
  done
}
if [ "$reference" = 1 ] || [ "$energy_reference" = 1 ]; then
  refruns="$out/reference"; mkdir -p "$refruns"
  energy_reference_runs
  if [ "$energy_reference" = 1 ]; then
    $PY "$eval_py" energy-reference "$refruns" "$ref_json" || exit 1
    exit 0
  fi
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
      --set "Adaptation/Mode=none" --set "Contact solver/Solver=monolithic" \
      --set "Contact pair S/Penalty=$c" \
      --set "Body omega1/Element/Degree=2" --set "Body omega2/Element/Degree=2" \
      --set "Body omega1/Mesh/Initial refinement=$r" --set "Body omega2/Mesh/Initial refinement=$r" \
      > "$refruns/$name.log" 2>&1 || { echo "reference run $name failed" >&2; exit 1; }
  done
  $PY "$eval_py" reference "$refruns" "$ref_json" "$ref_profile" || exit 1
  $PY "$eval_py" energy-reference "$refruns" "$ref_json" || exit 1
  exit 0
fi
[ -f "$ref_json" ] || { echo "error_vs_time.sh: no reference $ref_json (run with --reference)" >&2; exit 1; }

runs="$out/runs"; [ "$resume" = 1 ] || rm -rf "$runs"; mkdir -p "$runs"
manifest="$out/manifest.txt"; : > "$manifest"
failed=0
[ -n "$repeat" ] || { if [ "$quick" = 1 ]; then repeat=1; else repeat=3; fi; }
echo "machine load before: $(uptime)" | tee "$out/load.txt"

# run NAME SERIES PROBLEM DEG1 DEG2 SETTING [--set ...]: one run of the
# paper's scene; PROBLEM is the reference it is measured against (penalty:
# the penalised problem of the scene; exact: exact contact). The run is
# repeated (into NAME.rep2, ...) for the median of the timings, unless it
# took more than 30 s; the evaluation checks that the repeats agree.
run() {
  local name=$1 series=$2 problem=$3 d1=$4 d2=$5 setting=$6
  shift 6
  [ -z "$part" ] || [ "$problem" = "$part" ] || return 0
  echo "$name|$series|$problem|$d1|$d2|$setting" >> "$manifest"
  local k dir
  for k in $(seq 1 "$repeat"); do
    dir="$runs/$name"; [ "$k" = 1 ] || dir="$runs/$name.rep$k"
    if [ "$resume" = 1 ] && [ -f "$dir/summary.json" ]; then
      awk '/^wall time/ { exit !($3 > 30) }' "$dir.log" && break
      continue
    fi
    if ! "$exe" "${run_scene:-$scene}" --output "$dir" "${common[@]}" "$@" > "$dir.log" 2>&1; then
      echo "FAILED: $name (exit status $?, see $dir.log)" >&2; failed=1; break
    fi
    [ "$quick" = 1 ] || grep -E "^wall time" "$dir.log" | sed "s/^/  $(basename "$dir"): /"
    grep -qE "^wall time [0-9.]+ s" "$dir.log" && \
      awk '/^wall time/ { exit !($3 > 30) }' "$dir.log" && break
  done
}
# Both bodies at refinement level r (array LV); both bodies of degree p (DG).
lv() { LV=(--set "Body omega1/Mesh/Initial refinement=$1" --set "Body omega2/Mesh/Initial refinement=$1"); }
dg() { DG=(--set "Body omega1/Element/Degree=$1" --set "Body omega2/Element/Degree=$1"); }

if [ "$quick" = 1 ]; then
  U_MONO="0"; U_P2="0"; U_DD="0"; U_DD_P2="0"; U_FIXED="0"; U_AUTO="0"; U_AL="0"; U_AL_P2="0"
  KN1="1"; KC1="1"; KN2="1"; KC2="1"; K_CYC_AL="1"; T_ERR1="0.1"; T_ERR2="0.05"
  P_CAP="100"; S_DELTA="0.2"; S_DELTA_FIXED="0.2"
else
  U_MONO="0 1 2 3 4 5"; U_P2="0 1 2 3 4"; U_DD="0 1 2 3 4 5"; U_DD_P2="0 1 2 3 4 5"
  U_FIXED="0 1 2 3 4"; U_AUTO="0 1 2 3 4"; U_AL="0 1 2 3 4 5"; U_AL_P2="0 1 2 3"
  KN1="2 4 5 6 7 8"; KC1="4 6 8 10 11 12 13"; KN2="2 3 4 5 6 7"; KC2="4 6 8 10 12"
  K_CYC_AL="2 3 4 5 6 7 8"
  T_ERR1="0.04 0.02 0.014 0.01 0.007 0.005"; T_ERR2="0.01 0.005 0.002 0.001 0.0007 0.0005"
  P_CAP="300 1200 5000 20000"; S_DELTA="0.2 0.1 0.07 0.05 0.035"; S_DELTA_FIXED="0.1 0.05"
fi

# Uniform refinement of both bodies (Omega_1 triangles and Omega_2
# quadrilaterals on the same 16 x 4 x 4^r squares), fixed meshes.
none=(--set "Adaptation/Mode=none")
mono=(--set "Contact solver/Solver=monolithic")
for r in $U_MONO; do lv $r; run "uni-mono-p1-r$r" uniform-monolithic-P1 penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" "${mono[@]}"; done
dg 2
for r in $U_P2; do lv $r; run "uni-mono-p2-r$r" uniform-monolithic-P2 penalty 2 2 "r=$r" "${none[@]}" "${LV[@]}" "${mono[@]}" "${DG[@]}"; done
for r in $U_DD; do lv $r; run "uni-dd-anderson-r$r" uniform-DD-anderson-P1 penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "$(relax anderson)"; done
for r in $U_DD_P2; do lv $r; run "uni-dd-anderson-p2-r$r" uniform-DD-anderson-P2 penalty 2 2 "r=$r" "${none[@]}" "${LV[@]}" "${DG[@]}" --set "$(relax anderson)"; done
for r in $U_FIXED; do lv $r; run "uni-dd-fixed-r$r" uniform-DD-fixed-P1 penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "$(relax fixed)"; done
for r in $U_AUTO; do lv $r; run "uni-dd-auto-r$r" uniform-DD-auto-P1 penalty 1 1 "r=$r" "${none[@]}" "${LV[@]}" --set "$(relax auto)"; done
for r in $U_AL; do lv $r; run "uni-ddnewton-exact-r$r" uniform-DDnewton-exact-P1 exact 1 1 "r=$r" "${none[@]}" "${LV[@]}" "${AL[@]}"; done

# Adaptive runs: both bodies adapted (Omega_1's triangles too), cells
# ranked over both bodies together, Max level 12 (the scene's 7 would stop
# the refinement at the contact edges and corners first), Anderson
# relaxation unless the series says fixed (the paper's gamma = 0.02).
adapt=(--set "Adaptation/Bodies=omega1, omega2" --set "Adaptation/Max level=12" --set "$(relax anderson)")
# Kelly: nested (DD to convergence, then refine the 30 % largest) and
# combined (Fig. 2, one DD step per adaptation step) with Doerfler 50 %.
kelly_n=(--set "Adaptation/Mode=nested" --set "Adaptation/Estimator=kelly" --set "Adaptation/Marking=fraction" --set "Adaptation/Fraction=0.3")
kelly_c=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=kelly" --set "Adaptation/Marking=doerfler" --set "Adaptation/Fraction=0.5")
for p in 1 2; do
  dg $p; cyc=KN$p
  for n in ${!cyc}; do run "kelly-nested-p$p-c$n" kelly-nested-P$p penalty $p $p "cycles=$n" "${adapt[@]}" "${kelly_n[@]}" "${DG[@]}" --set "Adaptation/Max cycles=$n"; done
  cyc=KC$p
  for n in ${!cyc}; do run "kelly-combined-p$p-c$n" kelly-combined-doerfler-P$p penalty $p $p "cycles=$n" "${adapt[@]}" "${kelly_c[@]}" "${DG[@]}" --set "Adaptation/Max cycles=$n"; done
done
# Adaptive exact contact starts from the uniform series' coarsest mesh
# (both bodies at r = 0) and refines by Doerfler marking (0.7 at degree 1,
# whose solution is smooth enough that uniform refinement keeps its
# O(h^2) in force and peak pressure, 0.5 at degree 2); S_2 is graded
# against S_1 (grade_contact_zone()).
r0=(--set "Body omega1/Mesh/Initial refinement=0" --set "Body omega2/Mesh/Initial refinement=0")
kelly_al=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=kelly" --set "Adaptation/Marking=doerfler")
fb_al=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=fem-bem-scaled" --set "Adaptation/Marking=doerfler" --set "Adaptation/Fraction=0.5")
dg 2
for r in $U_AL_P2; do lv $r; run "uni-ddnewton-exact-p2-r$r" uniform-DDnewton-exact-P2 exact 2 2 "r=$r" "${none[@]}" "${LV[@]}" "${DG[@]}" "${AL[@]}"; done
dg 1
for n in $K_CYC_AL; do run "kelly-combined-ddnewton-exact-p1-c$n" kelly-combined-DDnewton-exact-P1 exact 1 1 "cycles=$n" "${adapt[@]}" "${r0[@]}" "${kelly_al[@]}" --set "Adaptation/Fraction=0.7" --set "Adaptation/Max cycles=$n" "${AL[@]}"; done
dg 2
for n in $K_CYC_AL; do run "kelly-combined-ddnewton-exact-p2-c$n" kelly-combined-DDnewton-exact-P2 exact 2 2 "cycles=$n" "${adapt[@]}" "${r0[@]}" "${kelly_al[@]}" --set "Adaptation/Fraction=0.5" --set "Adaptation/Max cycles=$n" "${DG[@]}" "${AL[@]}"; done
for n in $K_CYC_AL; do run "fembem-combined-ddnewton-exact-p2-c$n" fembem-scaled-combined-DDnewton-exact-P2 exact 2 2 "cycles=$n" "${adapt[@]}" "${r0[@]}" "${fb_al[@]}" --set "Adaptation/Max cycles=$n" "${DG[@]}" "${AL[@]}"; done
dg 1

# FEM-BEM (scale-consistent) with Doerfler 50 % and the target-error stop
# (Adaptation/Target error, on the estimator's global estimate), nested and
# combined (the paper's Fig. 2), degree 1 and 2.
fb_n=(--set "Adaptation/Mode=nested" --set "Adaptation/Estimator=fem-bem-scaled" --set "Adaptation/Marking=doerfler" --set "Adaptation/Fraction=0.5")
fb_c=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=fem-bem-scaled" --set "Adaptation/Marking=doerfler" --set "Adaptation/Fraction=0.5")
for p in 1 2; do
  dg $p; tl=T_ERR$p
  for t in ${!tl}; do run "fembem-nested-p$p-t$t" fembem-scaled-nested-doerfler-P$p penalty $p $p "target=$t" "${adapt[@]}" "${fb_n[@]}" "${DG[@]}" --set "Adaptation/Target error=$t"; done
  for t in ${!tl}; do run "fembem-combined-p$p-t$t" fembem-scaled-combined-doerfler-P$p penalty $p $p "target=$t" "${adapt[@]}" "${fb_c[@]}" "${DG[@]}" --set "Adaptation/Target error=$t"; done
done
dg 1
# The paper's marking (threshold delta on the scale-consistent (27)), with
# Anderson and with the paper's gamma = 0.02; and (27) as printed, which
# marks nearly every cell, so Max cells decides the mesh.
scaled=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=fem-bem-scaled" --set "Adaptation/Marking=threshold")
for d in $S_DELTA; do run "fembem-threshold-d$d" fembem-scaled-combined-threshold-P1 penalty 1 1 "delta=$d" "${adapt[@]}" "${scaled[@]}" --set "Adaptation/Delta=$d"; done
for d in $S_DELTA_FIXED; do run "fembem-threshold-fixed-d$d" fembem-scaled-combined-threshold-fixed-P1 penalty 1 1 "delta=$d" "${adapt[@]}" "${scaled[@]}" --set "Adaptation/Delta=$d" --set "$(relax fixed)"; done
printed=(--set "Adaptation/Mode=combined" --set "Adaptation/Estimator=fem-bem" --set "Adaptation/Delta=0.1")
for m in $P_CAP; do run "fembem-printed-m$m" fembem-printed-combined-P1 penalty 1 1 "max cells=$m" "${adapt[@]}" "${printed[@]}" --set "Adaptation/Max cells=$m"; done

# Hertz (prm/hertz.prm): two large blocks, refined toward the contact
# (Box refinement b), measured against the closed form at the computed
# force (doc/verification.md §2.2): peak pressure, half-width (least-squares
# fit of p^2 against x1^2) and the pressure profile. Exact contact (the
# scene's dd-newton) and plain penalty with Anderson.
if [ "$quick" = 1 ]; then H_BOX="3"; else H_BOX="3 4 5 6 7 8"; fi
run_scene="$root/prm/hertz.prm"
for b in $H_BOX; do run "hertz-exact-b$b" hertz-DD-newton-exact hertz 1 1 "box refinement=$b" --set "Body upper/Mesh/Box refinement=$b" --set "Body lower/Mesh/Box refinement=$b"; done
for b in $H_BOX; do run "hertz-penalty-b$b" hertz-DD-anderson-penalty hertz 1 1 "box refinement=$b" --set "Contact solver/Solver=dd" --set "Contact solver/Domain decomposition/Relaxation=anderson" --set "Body upper/Mesh/Box refinement=$b" --set "Body lower/Mesh/Box refinement=$b" --set "Contact pair S/Formulation=penalty"; done
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
[ -n "$part" ] && { F_Q1=""; F_Q2=""; F_P1=""; F_P2=""; }
for r in $F_Q1; do floor_run quadrilateral 1 $r; done
for r in $F_Q2; do floor_run quadrilateral 2 $r; done
for r in $F_P1; do floor_run triangle 1 $r; done
for r in $F_P2; do floor_run triangle 2 $r; done
floor_csv="$out/floor.csv"
if [ -n "$part" ]; then
  cp "$root/doc/error-vs-time-floor.csv" "$floor_csv"
else
  $PY "$eval_py" floor "$runs" "$floor_csv" || failed=1
fi

if [ "$quick" = 1 ]; then csv="$out/error-vs-time.csv"; else csv="$root/doc/error-vs-time.csv"; fi
if [ -n "$part" ]; then
  # The new rows of PROBLEM in place of the old ones, the others kept.
  $PY "$eval_py" evaluate "$manifest" "$runs" "$ref_json" "$ref_profile" "$floor_csv" "$out/part.csv" "$out/targets.md" || failed=1
  $PY - "$csv" "$out/part.csv" "$part" <<'EOF' || failed=1
import csv, sys
old = list(csv.DictReader(open(sys.argv[1])))
new = list(csv.DictReader(open(sys.argv[2])))
fields = csv.DictReader(open(sys.argv[2])).fieldnames
rows = [r for r in old if r["problem"] != sys.argv[3]] + new
with open(sys.argv[1], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
    w.writeheader()
    w.writerows(rows)
EOF
else
  $PY "$eval_py" evaluate "$manifest" "$runs" "$ref_json" "$ref_profile" "$floor_csv" "$csv" "$out/targets.md" || failed=1
fi
if [ "$quick" = 0 ]; then
  [ -n "$part" ] || cp "$floor_csv" "$root/doc/error-vs-time-floor.csv"
  [ -n "$part" ] || cp "$out/load.txt" "$root/doc/error-vs-time-load.txt"
  # (targets.md covers every series: a --part run leaves it.)
  mkdir -p "$root/doc/error-vs-time"
  [ -n "$part" ] || cp "$out/targets.md" "$root/doc/error-vs-time/targets.md"
  if [ "$plot" = 1 ]; then
    $PY "$root/scripts/plot_error_vs_time.py" "$csv" "$ref_json" "$root/doc/error-vs-time" || failed=1
  fi
fi
[ "$failed" = 0 ] && echo "error_vs_time: all runs finished, all errors finite"
exit $failed
