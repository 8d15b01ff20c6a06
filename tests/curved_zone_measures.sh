#!/usr/bin/env bash
# DESCRIPTION: contact measures on a curved zone do not depend on the
# origin: prm/hertz_cylinder.prm as shipped (contact point at the origin)
# and moved so that the cylinder's centre is at the origin give the same
# half-width (by arc length along S_1; the former projection gave 0.0147
# instead of 0.1445 there) and normal force, and the half-width meets
# Hertz's a = sqrt(4 P R / (pi E*)) of the computed normal force P within
# one face of the zone (0.03, the mesh size at the contact point)
# usage: curved_zone_measures.sh DDCONTACT_EXECUTABLE SOURCE_DIR
set -u
source "$(dirname "$0")/record_checks.sh"
exe="$1"; src="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$exe" --output "$work/shipped" "$src/prm/hertz_cylinder.prm" \
  --set "Output/Write vtu=false" >"$work/shipped.log" 2>&1
check $? "the shipped scene runs"
"$exe" --output "$work/moved" "$src/prm/hertz_cylinder.prm" \
  --set "Output/Write vtu=false" \
  --set "Body cylinder/Mesh/File=$src/tests/half_cylinder_centred.geo" \
  --set "Body block/Mesh/Corner 1=-10, -15" --set "Body block/Mesh/Corner 2=10, -5" \
  --set "Body block/Mesh/Refinement box=-0.8, -5.2, 0.8, -4.8" >"$work/moved.log" 2>&1
check $? "the scene moved by (0, -5) runs"
python3 - "$work/shipped/summary.json" "$work/moved/summary.json" <<'PY'
import json, math, sys
E, nu, R, h = 1000., 0.3, 5., 0.03
failures = 0
def check(what, error, tolerance):
    global failures
    ok = error <= tolerance
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {what}: {error:.3g} (tolerance {tolerance:.3g})")
pairs = [json.load(open(f))["contact"][0] for f in sys.argv[1:]]
a0, a1 = (c["half_width"] for c in pairs)
P0, P1 = (c["normal_force"] for c in pairs)
# The two meshes are the same up to gmsh's round-off: the same numbers to
# far below a face.
check("half-width at the two origins, relative difference", abs(a1 - a0) / a0, 1e-3)
check("normal force at the two origins, relative difference", abs(P1 - P0) / P0, 1e-3)
Estar = E / (2 * (1 - nu**2))
for name, a, P in (("shipped", a0, P0), ("moved", a1, P1)):
    hertz = math.sqrt(4 * P * R / (math.pi * Estar))
    check(f"{name}: |half-width - Hertz a| ({a:.5f} against {hertz:.5f})", abs(a - hertz), h)
sys.exit(1 if failures else 0)
PY
check $? "curved zone: the same measures at both origins, Hertz's half-width"
[ $failures -eq 0 ] && echo "all checks passed"
[ $failures -eq 0 ]
