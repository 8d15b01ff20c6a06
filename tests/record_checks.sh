# Shared by the shell tests of a run's record (output_integrity.sh,
# output_ownership.sh, signal_record.sh); sourced, not run.
failures=0
check() { # check CONDITION_EXIT_CODE WHAT
  if [ "$1" -eq 0 ]; then echo "ok   $2"; else echo "FAIL $2"; failures=$((failures + 1)); fi
}
# field_of FILE KEY: a top-level entry of a summary.json (None if absent).
field_of() { python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get(sys.argv[2]))" "$1" "$2" 2>/dev/null; }
status_of() { field_of "$1" status; }
