#!/usr/bin/env bash
# DESCRIPTION: the floating pin of issue 59 on the two Gmsh meshes on which
# dd-newton's first Newton step gave a NaN (a CG that divided 0 by 0 once
# a single node was forced): a pin held only by contact in a bore,
# loaded by a body force, converges in at most 15 Newton steps (the
# issue's target; 8 measured), its self-checks pass, and the contact force
# on the pin balances the body force it carries (the load integrated over
# the pin's mesh, 100.287 for P = 100 on the exact annulus) to the
# self-checks' limit, 100 x Contact solver/Tolerance
# usage: pin_in_bore.sh DDCONTACT_EXECUTABLE SOURCE_DIR
set -u
source "$(dirname "$0")/record_checks.sh"
exe="$1"; src="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$exe" --output "$work/pin" "$src/tests/scenes/pin_in_bore/pin.prm" \
  --set "Output/Write vtu=false" >"$work/pin.log" 2>&1
check $? "the pin converges (exit 0)"
python3 - "$work/pin/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
failures = 0
def check(what, ok):
    global failures
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {what}")
check(f"status converged ({s['status']})", s["status"] == "converged")
check(f"at most 15 Newton steps ({s.get('newton_steps')})",
      0 < s.get("newton_steps", 0) <= 15)
check("every self-check passed", s["self_checks"]["passed"])
pin = next(b for b in s["bodies"] if b["name"] == "pin")
load, contact = pin["applied_load"][1], pin["contact_force"][1]
check(f"the contact force {contact:.6g} balances the body force {load:.6g} "
      "to 1e-6", abs(contact + load) <= 1e-6 * abs(load) and load < 0)
sys.exit(1 if failures else 0)
PY
check $? "the pin's numbers"
[ $failures -eq 0 ] && echo "all checks passed"
[ $failures -eq 0 ]
