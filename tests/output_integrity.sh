#!/usr/bin/env bash
# DESCRIPTION: a run leaves a true record (doc/reliability.md): a second run
# into a directory in use is refused in one line; a rerun interrupted by
# SIGTERM ends with exit 6, summary.json "interrupted", its history, no file
# of the earlier run and no half file; a read-only or full file system ends
# in one line with exit 7 (those two only where tmpfs can be mounted, as
# root; otherwise skipped with a message)
# usage: output_integrity.sh DDCONTACT_EXECUTABLE SOURCE_DIR
set -u
source "$(dirname "$0")/record_checks.sh"
exe="$1"; src="$2"
paper="$src/prm/paper_two_bodies.prm"
work=$(mktemp -d); trap 'umount "$work"/ro "$work"/full 2>/dev/null; rm -rf "$work"' EXIT

out="$work/run"
# 1. A complete adaptive run: several output steps.
"$exe" --output "$out" "$paper" --set "Body omega1/Mesh/Initial refinement=1" >/dev/null 2>&1
check $? "first run completes"
[ -f "$out/bodies-0003.pvtu" ]; check $? "first run wrote several steps"

# 2. A rerun without adaptation (one step), slow enough to be caught.
"$exe" --output "$out" "$paper" --set "Adaptation/Mode=none" \
  --set "Body omega1/Mesh/Initial refinement=4" --set "Body omega2/Mesh/Initial refinement=4" \
  >"$work/rerun.log" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  grep -q "DD " "$work/rerun.log" 2>/dev/null && break
  sleep 0.1
done
[ "$(status_of "$out/summary.json")" = "running" ]; check $? "summary.json says running while the rerun works"
[ ! -f "$out/bodies-0003.pvtu" ]; check $? "the earlier run's steps are gone"

# 3. A second run into the same directory is refused in one line.
"$exe" --output "$out" "$paper" >"$work/second.out" 2>"$work/second.err"
code=$?
[ $code -eq 1 ] && [ "$(grep -c "^ddcontact: error: Output directory: .* is in use by another run" "$work/second.err")" -eq 1 ]
check $? "a second run into the directory is refused (exit $code: $(head -1 "$work/second.err"))"

# 4. SIGTERM ends the rerun after its current step.
kill -TERM $pid
wait $pid
code=$?
[ $code -eq 6 ]; check $? "SIGTERM: exit code 6 (got $code)"
[ "$(status_of "$out/summary.json")" = "interrupted" ]; check $? "summary.json status interrupted"
[ -s "$out/history.csv" ]; check $? "the history so far is written"
[ -z "$(ls "$out"/*.partial 2>/dev/null)" ]; check $? "no half file left"
[ ! -f "$out/.ddcontact.lock" ]; check $? "the lock is released"
[ ! -f "$out/bodies-0003.pvtu" ] && [ ! -f "$out/statistics.csv" ]; check $? "no result of the earlier run remains"

# 5. Read-only and full file systems (tmpfs, root only).
mkdir -p "$work/ro" "$work/full"
if mount -t tmpfs -o ro,size=1m tmpfs "$work/ro" 2>/dev/null; then
  "$exe" --output "$work/ro/x" "$paper" >/dev/null 2>"$work/ro.err"
  code=$?
  # (The directory itself cannot be made: an input error names it.)
  [ $code -eq 1 ] || [ $code -eq 7 ]; check $? "read-only file system: exit $code, $(head -1 "$work/ro.err")"
  [ "$(wc -l <"$work/ro.err")" -eq 1 ]; check $? "... in one line"
  mkdir -p "$work/rw" && mount -t tmpfs -o size=1m tmpfs "$work/full"
  mkdir "$work/full/x" && mount -o remount,ro "$work/full" 2>/dev/null
  "$exe" --output "$work/full/x" "$paper" >/dev/null 2>"$work/ro2.err"
  code=$?
  [ $code -eq 7 ] && [ "$(wc -l <"$work/ro2.err")" -eq 1 ]; check $? "read-only existing directory: exit 7 in one line (exit $code: $(head -1 "$work/ro2.err"))"
  umount "$work/full"
  mount -t tmpfs -o size=48k tmpfs "$work/full"
  "$exe" --output "$work/full/x" "$paper" --set "Adaptation/Mode=none" >/dev/null 2>"$work/full.err"
  code=$?
  [ $code -eq 7 ] && [ "$(wc -l <"$work/full.err")" -eq 1 ]; check $? "full file system: exit 7 in one line (exit $code: $(head -1 "$work/full.err"))"
  [ -z "$(find "$work/full/x" -name '*.partial')" ]; check $? "... and no half file"
  [ -z "$(find "$work/full/x" -empty -type f)" ]; check $? "... and no empty file"
else
  echo "skip read-only and full file systems: tmpfs cannot be mounted here (needs root)"
fi

# 6. Honest reports: a target the adaptation stops above, and units off
# by 1e6.
"$exe" --output "$work/target" "$paper" --set "Adaptation/Target error=0.01" \
  --set "Adaptation/Max cells=300" >/dev/null 2>"$work/target.err"
code=$?
[ $code -eq 5 ] && [ "$(status_of "$work/target/summary.json")" = "target_not_reached" ] &&
  grep -q "^ddcontact: error: Adaptation/Target error 0.01 not reached: .*Max cells (300)" "$work/target.err"
check $? "a missed Target error: exit 5, target_not_reached, naming Max cells (exit $code: $(head -1 "$work/target.err"))"
"$exe" --output "$work/units" "$src/prm/hertz_force.prm" --set "Constants=q=191390, R=5" \
  --set "Output/Write vtu=false" >/dev/null 2>&1
python3 - "$work/units/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
ok = any("largest strain" in w and "units" in w for w in s["warnings"])
sys.exit(0 if ok else 1)
PY
check $? "a load 1e6 too large: the strain warning names units"
"$exe" --output "$work/units_ok" "$src/prm/hertz_force.prm" --set "Output/Write vtu=false" >/dev/null 2>&1
python3 - "$work/units_ok/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
sys.exit(0 if s["warnings"] == [] and s["bodies"][0]["largest_strain"] < 0.05 else 1)
PY
check $? "... and the shipped load gives no warning"

echo "$failures failed"
[ $failures -eq 0 ]
