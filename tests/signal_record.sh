#!/usr/bin/env bash
# DESCRIPTION: a signal leaves a true record every time
# (doc/reliability.md): the first signal writes summary.json "interrupted"
# with the last completed step at once, so that a second signal, or
# SIGKILL right after it, ends the process with the record already true;
# and SIGTERM to mpirun, which forwards it to its processes and kills them
# about 2 s later, maybe before the current step ends, N times in a row.
# Never "running" after the end.
# usage: signal_record.sh DDCONTACT_EXECUTABLE SOURCE_DIR [N]
set -u
source "$(dirname "$0")/record_checks.sh"
exe="$1"; src="$2"; n="${3:-10}"
scene="$src/prm/paper_two_bodies.prm"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1 \
  DEAL_II_NUM_THREADS=1
# One process in a long step (a fine mesh, written up at the end, where
# no check for signals comes for seconds): SIGTERM, and 0.3 s later
# SIGKILL, as mpirun does. The record is the signal handler's, or the
# run's own if the run ended first: never "running".
for second in TERM KILL; do
  out="$work/serial"
  rm -f "$out/summary.json"
  "$exe" --output "$out" "$src/prm/two_bodies.prm" --set "Output/Write vtu=false" \
    --set "Body lower/Mesh/Initial refinement=4" >"$work/log" 2>&1 &
  pid=$!
  for _ in $(seq 1 1200); do
    [ "$(field_of "$out/summary.json" status)" = "running" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.05
  done
  kill -TERM $pid; sleep 0.3; kill -$second $pid 2>/dev/null
  { wait $pid; } 2>/dev/null
  code=$?
  status=$(field_of "$out/summary.json" status)
  if [ "$status" = "interrupted" ] || [ "$status" = "completed" ]; then
    echo "ok   one process, SIGTERM then SIG$second: exit $code, status $status"
  else
    echo "FAIL one process, SIGTERM then SIG$second: exit $code, status $status"
    failures=$((failures + 1))
  fi
done

for i in $(seq 1 "$n"); do
  out="$work/run"
  # Load steps, so that some steps complete before the signal.
  mpirun -np 2 "$exe" --output "$out" "$scene" --set "Adaptation/Mode=none" \
    --set "Output/Write vtu=false" --set "Loading/Steps=20" \
    >"$work/log" 2>&1 &
  pid=$!
  # Wait for the first load steps, then a little more (a different moment
  # of the step each time).
  for _ in $(seq 1 1200); do
    grep -q "load step 3" "$work/log" 2>/dev/null && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.05
  done
  sleep "0.$((i * 7 % 10))"
  kill -TERM $pid
  { wait $pid; } 2>/dev/null
  code=$?
  status=$(field_of "$out/summary.json" status)
  last=$(field_of "$out/summary.json" last_completed_step)
  if [ $code -ne 0 ] && [ "$status" = "interrupted" ] && [ "$last" != "None" ]; then
    echo "ok   run $i: exit $code, status $status, last completed step: $last"
  else
    echo "FAIL run $i: exit $code, status $status, last completed step: $last"
    tail -3 "$work/log" | sed 's/^/    /'
    failures=$((failures + 1))
  fi
done
if [ $failures -gt 0 ]; then echo "$failures of $n runs failed"; exit 1; fi
echo "all $n runs left a true record"
