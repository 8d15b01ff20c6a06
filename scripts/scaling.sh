#!/usr/bin/env bash
# Study (not a test): strong scaling of the DD from 1 to 2 MPI processes on
# the paper's scene refined to about 1e6 unknowns (both bodies at Initial
# refinement 6: 2 x 526850 dofs), fixed meshes, Anderson. Four runs: one
# process with one thread (the bodies solved one after the other), one
# process with two threads (the bodies solved by concurrent tasks), two
# processes with one thread each (each body on its own process), and two
# processes with every body partitioned between both (Body owners = all:
# MUMPS over the two processes, the bodies one after the other). Writes
# doc/scaling.csv. Then the memory of the mesh layouts, with both bodies
# of quadrilaterals so that both can be distributed: one process, two
# processes with shared meshes, two with distributed (p4est) meshes;
# writes doc/scaling-memory.csv. doc/scaling.md discusses both. Usage:
#   scripts/scaling.sh [REFINEMENT [PART [EXECUTABLE]]]   (REFINEMENT 6 by
#   default, 5 gives 2.6e5 unknowns; PART all (default), time or memory;
#   without EXECUTABLE it installs, builds and uses build/ddcontact)
set -euo pipefail
cd "$(dirname "$0")/.."
r=${1:-6}
part=${2:-all}
exe=$(scripts/release_executable.sh "${3:-}")
out=doc/scaling-runs
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
common=(prm/paper_two_bodies.prm
        --set "Adaptation/Mode=none" --set "Output/Write vtu=false"
        --set "Body omega1/Mesh/Initial refinement=$r"
        --set "Body omega2/Mesh/Initial refinement=$r"
        --set "Contact solver/Domain decomposition/Relaxation=anderson")
run() { # name, processes, threads, further --set options
  echo "== $1"
  # --bind-to none: Open MPI binds each of up to two processes to one core,
  # and the two threads of np1_threads2 would then share that core.
  DEAL_II_NUM_THREADS=$3 mpirun --oversubscribe --bind-to none -np "$2" "$exe" "${common[@]}" \
    "${@:4}" --output "$out/$1" > "$out/$1.log"
  grep -E "contact S:|wall time" "$out/$1.log" | sed 's/^/   /'
}
if [ "$part" != memory ]; then
run np1_threads1 1 1
run np1_threads2 1 2
run np2_threads1 2 1
run np2_all 2 1 --set "Parallel/Body owners=all"
python3 - "$out" doc/scaling.csv <<'PY'
import json, sys
out, csv = sys.argv[1], sys.argv[2]
phases = ["setup", "contact setup", "contact solve", "body solves",
          "exchange between processes"]
with open(csv, "w") as f:
    f.write("run,processes,threads,dofs,dd_iterations,wall_s,"
            + ",".join(p.replace(" ", "_") + "_s" for p in phases)
            + ",contact_solve_per_iteration_s\n")
    for name, n, t in [("np1_threads1", 1, 1), ("np1_threads2", 1, 2),
                       ("np2_threads1", 2, 1), ("np2_all", 2, 1)]:
        s = json.load(open(f"{out}/{name}/summary.json"))
        dofs = sum(b["dofs"] for b in s["bodies"])
        tm = s["timings"]
        row = [name, n, t, dofs, s["dd_iterations"], f"{s['wall_time_s']:.3f}"]
        row += [f"{tm.get(p, 0.0):.3f}" for p in phases]
        row += [f"{tm['contact solve'] / s['dd_iterations']:.4f}"]
        f.write(",".join(str(x) for x in row) + "\n")
print(open(csv).read())
PY
fi
[ "$part" = time ] && exit 0

# Memory: the same scene with omega1 of quadrilaterals (2 x 526850 dofs
# at r = 6), every body on both processes.
quads=(--set "Body omega1/Element/Cell type=quadrilateral")
run quads_np1 1 1 "${quads[@]}"
run quads_np2_shared 2 1 "${quads[@]}" --set "Parallel/Body owners=all" \
  --set "Parallel/Mesh=shared"
run quads_np2_distributed 2 1 "${quads[@]}" --set "Parallel/Body owners=all" \
  --set "Parallel/Mesh=distributed"
python3 - "$out" doc/scaling-memory.csv <<'PY'
import json, sys
out, csv = sys.argv[1], sys.argv[2]
phases = ["setup", "contact setup", "contact solve", "body solves"]
with open(csv, "w") as f:
    f.write("run,processes,mesh,dofs,dd_iterations,force,wall_s,"
            + ",".join(p.replace(" ", "_") + "_s" for p in phases)
            + ",peak_memory_largest_process_mb,peak_memory_all_processes_mb"
            + ",mesh_memory_largest_process_mb\n")
    for name, n, mesh in [("quads_np1", 1, "serial"),
                          ("quads_np2_shared", 2, "shared"),
                          ("quads_np2_distributed", 2, "distributed")]:
        s = json.load(open(f"{out}/{name}/summary.json"))
        tm = s["timings"]
        row = [name, n, mesh, sum(b["dofs"] for b in s["bodies"]),
               s["dd_iterations"],
               f"{abs(s['contact'][0]['force'][0][1]):.6f}",
               f"{s['wall_time_s']:.3f}"]
        row += [f"{tm.get(p, 0.0):.3f}" for p in phases]
        row += [f"{s['peak_memory']['largest_process_mb']:.1f}",
                f"{s['peak_memory']['all_processes_mb']:.1f}",
                f"{sum(b['mesh_memory_mb'] for b in s['bodies']):.1f}"]
        f.write(",".join(str(x) for x in row) + "\n")
print(open(csv).read())
PY
