#!/usr/bin/env bash
# DESCRIPTION: doc/parameters.md is what scripts/generate_parameters_doc.py makes of the executable's --print-parameters-json
# usage: parameters_doc.sh DDCONTACT_EXECUTABLE SOURCE_DIR
# Regenerates the page into a temporary file and compares. A few seconds
# in a Debug build: the generator runs the executable twice, with
# --print-parameters-json (the entries) and --print-parameters (the units).
set -u
exe="$1"; src="$2"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT

if ! "${PYTHON:-python3}" "$src/scripts/generate_parameters_doc.py" "$exe" \
     --output "$work/parameters.md" >"$work/log" 2>&1; then
  cat "$work/log"
  echo "parameters_doc: scripts/generate_parameters_doc.py failed (above), so doc/parameters.md could not be checked"
  exit 1
fi
if ! cmp -s "$work/parameters.md" "$src/doc/parameters.md"; then
  echo "parameters_doc: doc/parameters.md differs from what the executable's --print-parameters-json gives; run scripts/generate_parameters_doc.py $exe"
  exit 1
fi
echo "parameters_doc: doc/parameters.md matches $exe --print-parameters-json"
