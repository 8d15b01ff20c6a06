#!/usr/bin/env bash
# Study (not a test) of issue 33: dd-newton on prm/hertz_large.prm with
# both bodies uniformly refined (Initial refinement R, no box refinement,
# fixed meshes), on 1, 2 and 4 MPI processes with one thread each
# (Body owners = auto: one body per process on 2, each body on a group of
# two on 4, oversubscribed on a 2-core machine). Per run: wall time, the
# contact solve, Newton steps and sets of body solves, and per process the
# owned dofs, peak memory and bytes sent (summary.json "processes"); the
# bytes of the steps are the total less the one whole solution each body's
# owner sends at the end. Writes doc/scaling-per-process.csv (one row per
# run and refinement; rows of other refinements are kept). With
# MAX_NEWTON=k in the environment each run stops after k Newton steps
# (status not_converged): enough for the peak memory, which is set by the
# bodies' factorizations and the first Robin factorization (step 2 on
# these meshes), at a fraction of the time. With LAYOUT=distributed every
# body is on every process (Body owners = all) on a p4est mesh, and keeps
# only each process's part of its vectors (ElasticBody::distribute_vectors());
# the default LAYOUT=auto is the default layout. Usage:
#   [MAX_NEWTON=k] [LAYOUT=auto|distributed] scripts/scaling_per_process.sh
#   [REFINEMENTS [PROCESSES [EXECUTABLE]]]   (default "5 6" and "1 2 4";
#   without EXECUTABLE it builds build/ddcontact)
set -euo pipefail
cd "$(dirname "$0")/.."
refinements=${1:-5 6}
layout=${LAYOUT:-auto}
processes=${2:-1 2 4}
exe=$(scripts/release_executable.sh "${3:-}")
out=doc/scaling-runs
csv=doc/scaling-per-process.csv
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for r in $refinements; do
  for n in $processes; do
    name=per_process_r${r}_np${n}
    args=(--set "Adaptation/Mode=none" --set "Output/Write vtu=false")
    if [ "$layout" = distributed ]; then
      name=${name}_distributed
      args+=(--set "Parallel/Body owners=all" --set "Parallel/Mesh=distributed")
    fi
    echo "== $name"
    if [ -n "${MAX_NEWTON:-}" ]; then
      args+=(--set "Contact solver/DD-Newton/Max Newton iterations=$MAX_NEWTON")
    fi
    for b in upper lower; do
      args+=(--set "Body $b/Mesh/Initial refinement=$r"
             --set "Body $b/Mesh/Box refinement=0")
    done
    DEAL_II_NUM_THREADS=1 mpirun --oversubscribe --bind-to none -np "$n" \
      "$exe" prm/hertz_large.prm "${args[@]}" --output "$out/$name" \
      > "$out/$name.log" || [ -n "${MAX_NEWTON:-}" ] # stopped on purpose
    python3 - "$out/$name/summary.json" "$csv" "$r" "$layout" <<'PY'
import json, os, sys
summary, csv, r, layout = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
s = json.load(open(summary))
procs = s["processes"]
dofs = [b["dofs"] for b in s["bodies"]]
steps = s["newton_steps"]
# The whole solution of every body goes out once at the end, from its
# group's first process to every other process (distributed vectors: only
# their ghosts, as in every step).
whole = [0] * len(procs)
for b, body in enumerate(s["bodies"] if layout == "auto" else []):
    first = int(s["body_owners"].split(",")[b].split(":")[1].split("-")[0])
    whole[first] += 8 * body["dofs"] * (len(procs) - 1)
step_bytes = max(p["bytes_sent"] - w for p, w in zip(procs, whole))
mem = [p["peak_memory_mb"] for p in procs]
row = [r, len(procs), layout, s["status"], sum(dofs), steps,
       s["body_solve_sets"],
       round(s["wall_time_s"], 2), round(s["timings"]["contact solve"], 2),
       round(max(mem)), round(sum(mem)),
       " ".join(str(p["owned_dofs"]) for p in procs),
       max(p["vector_entries"] for p in procs),
       round(step_bytes / steps), s["contact"][0]["force"][1][1]]
header = ("refinement,processes,layout,status,dofs,newton_steps,"
          "body_solve_sets,wall_s,contact_solve_s,peak_memory_max_mb,"
          "peak_memory_sum_mb,owned_dofs,vector_entries_max,"
          "bytes_per_newton_step,force")
rows = []
if os.path.exists(csv):
    rows = [l.rstrip("\n").split(",") for l in open(csv)][1:]
# Rows written before the layout and vector entries columns: the default
# layout, whole vectors (every body's dofs on every process).
rows = [l if len(l) == 15 else l[:2] + ["auto"] + l[2:11] + [l[3]] + l[11:]
        for l in rows]
rows = [l for l in rows if l[:3] != [str(r), str(len(procs)), layout]]
rows.append([str(x) for x in row])
rows.sort(key=lambda l: (int(l[0]), int(l[1]), l[2]))
rows = [",".join(l) for l in rows]
with open(csv, "w") as f:
    f.write(header + "\n" + "\n".join(rows) + "\n")
print("   " + ", ".join(f"{h}={v}" for h, v in zip(header.split(","), row)))
PY
  done
done
echo "wrote $csv"
