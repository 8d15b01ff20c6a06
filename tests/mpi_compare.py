"""Runs a scene with 1 and with N MPI processes and compares summary.json.

The bodies are solved on different processes (or process groups, with a
distributed direct solver) and their solutions broadcast
(BodyDistribution); everything else runs identically on every process, so
the two runs must agree: the same iteration counts, meshes and Uzawa
updates, and every number equal to 1e-10 relative (numbers inside a list
relative to the list's largest entry, so that a zero force component
compares at the scale of the force). Also checks that the N-process run
really solved the bodies on all N processes, and, with
--expect-repartition, that it moved a body to another process after
refinement. With --expect-distributed-mesh A,B it checks that exactly the
bodies A and B of the N-process run had p4est meshes (Parallel/Mesh),
and with --expect-shared-mesh that none had; --expect-distributed-vectors
checks that no process of the N-process run held a whole body vector. --allow-idle accepts
processes that solve no body (dd-newton keeps each body on one process).

With an iterative body solver, --tolerance T replaces 1e-10 by the
solver's accuracy.

usage: mpi_compare.py MPIRUN EXE SCENE OUTDIR [--np N] [--tolerance T]
                      [--expect-repartition] [--expect-distributed-mesh A,B]
                      [--expect-shared-mesh] [--allow-idle]
                      [--expect-distributed-vectors]
                      [--set Section/Entry=value ...]
                      [--parallel-set Section/Entry=value ...]
(--parallel-set applies to the N-process run only.)
"""
import json
import os
import subprocess
import sys

TOLERANCE = 1e-10
# Not results: where the bodies were solved, and how long it took.
IGNORED = {"mpi_processes", "body_owners", "wall_time_s", "timings",
           "distributed_mesh", "peak_memory", "mesh_memory_mb", "processes"}
# Changes of the iterate divided by its norm: already relative to the
# solution, so compared to 1e-10 absolutely (a different direct solver's
# round-off, 1e-16 of |u|, is 1e-10 of a residual of 1e-6).
# force_imbalance is already divided by the body's largest force.
# (self_checks: below.)
RELATIVE_TO_SOLUTION = {"dd_residual", "dd_increment", "force_imbalance"}


def run(mpirun, exe, scene, out, n, overrides):
    # One thread per process in both runs: deal.II's threaded loops change
    # the round-off with the number of threads, and a long Anderson
    # iteration can amplify 1e-16 into a different iteration count. A
    # process waiting for a message yields its core (tests/CMakeLists.txt,
    # DDCONTACT_MPI_ENV: on a busy machine the polling slowed a 10 s test
    # past its timeout).
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1",
               OMPI_MCA_mpi_yield_when_idle="1", DEAL_II_NUM_THREADS="1")
    command = [mpirun, "-np", str(n), exe, scene, "--output", out]
    for o in overrides:
        command += ["--set", o]
    result = subprocess.run(command, env=env, capture_output=True, text=True,
                            timeout=600)
    if result.returncode != 0:
        sys.exit(f"FAIL: {' '.join(command)} exited with {result.returncode}:\n"
                 f"{result.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), result.stdout


def compare(a, b, path, scale, failures):
    if isinstance(a, dict):
        inherited = scale
        for key in sorted(set(a) | set(b)):
            if key in IGNORED:
                continue
            if key not in a or key not in b:
                failures.append(f"{path}/{key}: only in one run")
                continue
            # The self-checks' values are relative measures too (their
            # limits are tied to the Tolerance).
            scale = 1.0 if key in RELATIVE_TO_SOLUTION or \
                key == "self_checks" else inherited
            # A body's reactions on the scale of the forces on the body: a
            # component that vanishes (the x reaction of rollers under a
            # vertical load) is round-off of them, 1e-13 of the load.
            if key == "reactions" and "contact_force" in a:
                scale = max(abs(f) for f in a["contact_force"] +
                            a.get("applied_load", []))
            # The largest rotation at the scale of the largest strain: both
            # are parts of the displacement gradient, and a body loaded
            # symmetrically (one cell under the paper's gap) has a rotation
            # of round-off, 1e-20 against a strain of 1e-3.
            if key == "largest_rotation" and "largest_strain" in a:
                scale = abs(a["largest_strain"])
            # The penetration u_1n + u_2n - g is a difference of
            # displacements as large as the approach (exact contact: 1e-4
            # of it), so it carries the approach's round-off.
            if key == "max_penetration" and "approach" in a:
                scale = abs(a["approach"])
            # A pair's friction results at the scale of its contact force:
            # the tangential force of a pressing step is round-off of the
            # normal force (1e-16 of it, and the two runs' round-off
            # differ), and the dissipation, zero there, is compared at the
            # work of that force over the zone's half-width, a bound of
            # anything friction can dissipate on the zone.
            if key in ("tangential_force", "dissipated_energy") and \
                    "force" in a and \
                    all(isinstance(f, float) for f in a["force"]):
                scale = max(abs(f) for f in a["force"])
                if key == "dissipated_energy":
                    scale *= abs(a.get("half_width") or 0.0)
            compare(a[key], b[key], f"{path}/{key}", scale, failures)
    elif isinstance(a, list):
        if len(a) != len(b):
            failures.append(f"{path}: lengths {len(a)} and {len(b)}")
            return
        numbers = [abs(x) for x in a if isinstance(x, float)]
        if scale is not None:
            numbers.append(scale)
        list_scale = max(numbers) if numbers else None
        for i, (x, y) in enumerate(zip(a, b)):
            compare(x, y, f"{path}[{i}]", list_scale, failures)
    elif isinstance(a, bool) or isinstance(a, int) or isinstance(a, str):
        if a != b:
            failures.append(f"{path}: {a} and {b}")
    elif isinstance(a, float):
        reference = max(scale or 0.0, abs(a), abs(b), 1e-300)
        if abs(a - b) > TOLERANCE * reference:
            failures.append(f"{path}: {a!r} and {b!r} differ by "
                            f"{abs(a - b) / reference:.2e} relative")
    elif a != b:
        failures.append(f"{path}: {a} and {b}")


def main():
    mpirun, exe, scene, out = sys.argv[1:5]
    rest = sys.argv[5:]
    expect_repartition = "--expect-repartition" in rest
    overrides = [rest[i + 1] for i, r in enumerate(rest) if r == "--set"]
    parallel = [rest[i + 1] for i, r in enumerate(rest)
                if r == "--parallel-set"]
    n = int(rest[rest.index("--np") + 1]) if "--np" in rest else 2
    if "--tolerance" in rest:
        global TOLERANCE
        TOLERANCE = float(rest[rest.index("--tolerance") + 1])
    one, _ = run(mpirun, exe, scene, out + "_np1", 1, overrides)
    two, log = run(mpirun, exe, scene, out + f"_np{n}", n,
                   overrides + parallel)

    failures = []
    compare(one, two, "", None, failures)
    # "omega1: 0-1, omega2: 2": every process must solve some body.
    owners = set()
    for item in two["body_owners"].split(","):
        first, _, last = item.split(":")[1].strip().partition("-")
        owners |= set(range(int(first), int(last or first) + 1))
    print(f"  1 process: {one.get('dd_iterations')} DD iterations; {n} "
          f"processes: {two.get('dd_iterations')}, bodies on processes "
          f"{two['body_owners']}")
    # dd-newton solves each body on one process; the others only share the
    # estimator's work (--allow-idle).
    if two["mpi_processes"] != n or (owners != set(range(n)) and
                                     "--allow-idle" not in rest):
        failures.append(f"the {n}-process run did not use all processes "
                        f"({two['body_owners']})")
    # summary.json's processes: every dof owned by exactly one process
    # (the owned dofs sum to the bodies' dofs), one entry per process, and
    # nothing sent by a single process.
    for run_summary, n_run in ((one, 1), (two, n)):
        processes = run_summary.get("processes", [])
        owned = sum(p["owned_dofs"] for p in processes)
        dofs = sum(b["dofs"] for b in run_summary["bodies"])
        print(f"  {n_run} process(es): owned dofs "
              f"{[p['owned_dofs'] for p in processes]} of {dofs}, bytes sent "
              f"{[p['bytes_sent'] for p in processes]}")
        if len(processes) != n_run or owned != dofs:
            failures.append(f"{n_run} process(es): processes lists "
                            f"{len(processes)} entries owning {owned} dofs, "
                            f"the bodies have {dofs}")
        if n_run == 1 and processes and processes[0]["bytes_sent"] != 0:
            failures.append("one process reports bytes sent")
    if expect_repartition and "bodies now solved on processes" not in log:
        failures.append("no body moved to another process after refinement")
    meshes = {b["name"]: b.get("distributed_mesh") for b in two["bodies"]}
    print(f"  p4est meshes: {meshes}")
    if "--expect-distributed-mesh" in rest:
        names = rest[rest.index("--expect-distributed-mesh") + 1].split(",")
        if sorted(n for n, d in meshes.items() if d) != sorted(names):
            failures.append(f"distributed meshes {meshes}, expected on "
                            f"{names}")
    # --expect-distributed-vectors: no process of the N-process run holds
    # a whole body vector: each stores its owned dofs plus ghosts (locally
    # relevant dofs and the contact traces), fewer entries than the bodies
    # have dofs, where whole vectors (the 1-process run) hold all of them.
    if "--expect-distributed-vectors" in rest:
        dofs = sum(b["dofs"] for b in two["bodies"])
        entries = [p["vector_entries"] for p in two["processes"]]
        print(f"  vector entries per process {entries} of {dofs} dofs")
        if (one["processes"][0]["vector_entries"] !=
                sum(b["dofs"] for b in one["bodies"])):
            failures.append("the 1-process run does not hold whole vectors")
        for p in two["processes"]:
            if not p["owned_dofs"] <= p["vector_entries"] < dofs:
                failures.append(f"process {p['rank']} stores "
                                f"{p['vector_entries']} entries, owns "
                                f"{p['owned_dofs']} of {dofs} dofs")
        # ... and only the constraint lines of the entries it stores,
        # fewer than all of the bodies' lines (the 1-process run's).
        lines = one["processes"][0]["constraint_lines"]
        stored = [p["constraint_lines"] for p in two["processes"]]
        print(f"  constraint lines per process {stored} of {lines}")
        if lines > 0 and max(stored) >= lines:
            failures.append(f"a process stores {max(stored)} constraint "
                            f"lines, as many as the bodies have ({lines})")
    if "--expect-shared-mesh" in rest and any(meshes.values()):
        failures.append(f"a body had a distributed mesh: {meshes}")
    for f in failures:
        print("  FAIL " + f)
    print("PASSED" if not failures else "FAILED")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
