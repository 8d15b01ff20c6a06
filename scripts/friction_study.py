#!/usr/bin/env python3
"""Friction study (doc/friction.md, section 5.3): prm/cattaneo_mindlin.prm
on refined meshes. For each refinement and solver (monolithic, dd-newton)
it runs:
- the shear in one step after the pressure (2 load steps);
- the shear in nine steps (10 load steps);
- the frictionless pressing of the same mesh (1 step, Friction = none), the
  time reference. dd-newton takes its exact contact; the monolithic solver
  takes exact contact on the nodes only with friction, so the nodal penalty
  c = 1e-8 stands in.

It writes doc/friction.csv with, per run: the unknowns, the Newton steps of
the normal step and the largest per shear step, the sets of body solves
(dd-newton), the wall time, Q/(mu P), and c/a fitted from the stick zone
against sqrt(1 - Q/(mu P)).

    scripts/friction_study.py [build/ddcontact] [--large] [--dd-newton-only]
                                                         (a Release build)

--large adds 256 x 128 cells refined twice toward the zone (the contact
cells of refinement 7, about 1e5 unknowns; an hour with the monolithic
solver). --dd-newton-only leaves the monolithic runs out.
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
EXE = ARGS[0] if ARGS else os.path.join(ROOT, "build", "ddcontact")
SCENE = os.path.join(ROOT, "prm", "cattaneo_mindlin.prm")
MU = 0.3
# The refinement box the friction studies of doc/friction.md (sections
# 5.3-5.5, doc/friction*.csv) were measured on: the scene's box before it
# reached 0.45 deep (section 5.2). Kept here so that the recorded tables
# come out again; the shipped box takes the peak pressure's bias from
# 0.9 % to 0.3 % and leaves c/a and the Newton steps alike.
STUDY_BOX = "-0.8, -0.2, 0.8, 0.2"


def study_box():
    """The --set entries of STUDY_BOX on both blocks."""
    return [f"Body {body}/Mesh/Refinement box={STUDY_BOX}"
            for body in ("upper", "lower")]


def fit_zero_of_root(xs, ys):
    """c of y = K sqrt(c^2 - x^2): the line through (x^2, y^2) at y = 0."""
    n = len(xs)
    X = [x * x for x in xs]
    Y = [y * y for y in ys]
    s1, s2 = sum(X), sum(v * v for v in X)
    t0, t1 = sum(Y), sum(a * b for a, b in zip(X, Y))
    slope = (n * t1 - s1 * t0) / (n * s2 - s1 * s1)
    intercept = (t0 - slope * s1) / n
    return math.sqrt(-intercept / slope)


def read_profile(out):
    """contact_S.csv of a run: its columns as lists of numbers."""
    rows = list(csv.DictReader(open(os.path.join(out, "contact_S.csv"))))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def write_csv(name, keys, rows):
    """The rows (dicts) with the columns keys into doc/<name>."""
    with open(os.path.join(ROOT, "doc", name), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        for r in rows:
            writer.writerow({k: r.get(k, "") for k in keys})


def solver_settings(solver):
    """The entries of a solver name: monolithic, dd-newton, or
    dd-newton-fixed-point (dd-newton with Coulomb linearization =
    fixed-point; the default is newton)."""
    settings = ["Contact solver/Solver=" + solver.replace("-fixed-point", "")]
    if solver == "dd-newton-fixed-point":
        settings.append("Contact solver/DD-Newton/Coulomb linearization=fixed-point")
    return settings


def run(level, steps, friction, out, subdivisions=8, solver="monolithic"):
    settings = solver_settings(solver) + study_box() + [
        f"Body upper/Mesh/Box refinement={level}",
        f"Body lower/Mesh/Box refinement={level}",
        f"Body upper/Mesh/Subdivisions={subdivisions}, {subdivisions // 2}",
        f"Body lower/Mesh/Subdivisions={subdivisions}, {subdivisions // 2}",
        "Output/Write vtu=false"]
    if not friction:
        # The same nodal multipliers without friction: the monolithic
        # solver takes exact contact on the nodes only with friction (else
        # by Uzawa updates on the points), so the penalty c = 1e-8 stands in.
        settings += ["Contact pair S/Friction=none", "Loading/Steps=1",
                     "Body upper/Boundary conditions/Dirichlet=3: xy: 0; -Delta"]
        if solver == "monolithic":
            settings += ["Contact pair S/Formulation=penalty",
                         "Contact pair S/Penalty=1e-8"]
    elif steps != 2:
        # Pressed in the first step, sheared in the others.
        n = steps
        settings += [f"Loading/Steps={n}",
                     "Body upper/Boundary conditions/Dirichlet=3: xy: "
                     f"U*max(0, ({n}*t - 1)/{n - 1}); -Delta*min(1, {n}*t)"]
    args = [EXE, "--output", out, SCENE]
    for s in settings:
        args += ["--set", s]
    log = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    summary = json.load(open(os.path.join(out, "summary.json")))
    # Newton steps per load step: the iterations printed under each step.
    per_step, count = [], None
    for line in log.splitlines():
        if line.startswith("load step"):
            if count is not None:
                per_step.append(count)
            count = 0
        # monolithic: "Newton 3: 40 active ..."; dd-newton: "Newton   3
        # residual ...".
        m = re.match(r"\s+Newton\s+(\d+)(: \d+ active|\s+residual)", line)
        if m and "cycles" not in line:
            count = (count or 0) + 1
    per_step.append(count or 0)
    # The monolithic solver's last Newton line of a solve checks the
    # settled set: not a step.
    if solver == "monolithic":
        per_step = [max(0, c - 1) for c in per_step]
    row = {"solver": solver, "refinement": level, "subdivisions": subdivisions,
           "load_steps": steps if friction else 1,
           "friction": "coulomb" if friction else "none",
           "unknowns": sum(b["dofs"] for b in summary["bodies"]),
           "newton_normal_step": per_step[0],
           "newton_max_shear_step": max(per_step[1:]) if len(per_step) > 1 else 0,
           "newton_all": summary["newton_steps"],
           "body_solve_sets": summary.get("dd_iterations", 0),
           "wall_time_s": summary["wall_time_s"],
           "contact_solve_s": summary["timings"].get("contact solve", 0.)}
    if friction:
        f = read_profile(out)
        x, p, t, w = f["x1"], f["pressure"], f["tangential_traction"], f["weight"]
        state = [int(s) for s in f["state"]]
        P = sum(a * b for a, b in zip(p, w))
        Q = sum(a * b for a, b in zip(t, w))
        a = fit_zero_of_root([xi for xi, pi in zip(x, p) if pi > 0],
                             [pi for pi in p if pi > 0])
        stick = [i for i in range(len(x)) if state[i] == 1]
        c = fit_zero_of_root([x[i] for i in stick],
                             [MU * p[i] - abs(t[i]) for i in stick])
        theory = math.sqrt(1 - Q / (MU * P))
        row.update({"Q_over_muP": Q / (MU * P), "a": a, "c_over_a": c / a,
                    "c_over_a_theory": theory,
                    "c_over_a_error": c / a / theory - 1})
    return row


def main():
    rows = []
    with tempfile.TemporaryDirectory() as work:
        # Refined toward the zone on the scene's 8 x 4 cells, and a mesh of
        # 256 x 128 cells refined twice (the contact cells of refinement 7,
        # about 1e5 unknowns).
        cases = [(8, 5), (8, 6), (8, 7), (8, 8), (8, 9)]
        if "--large" in sys.argv:
            cases.append((256, 2))
        solvers = ["dd-newton"] if "--dd-newton-only" in sys.argv \
            else ["monolithic", "dd-newton"]
        for subdivisions, level in cases:
            for solver in solvers:
                for steps, friction in ((1, False), (2, True), (10, True)):
                    out = os.path.join(
                        work,
                        f"{solver}_s{subdivisions}_r{level}_{steps}_{int(friction)}")
                    row = run(level, steps, friction, out, subdivisions, solver)
                    print(row, flush=True)
                    rows.append(row)
    keys = ["solver", "subdivisions", "refinement", "friction", "load_steps", "unknowns",
            "newton_normal_step", "newton_max_shear_step", "newton_all", "body_solve_sets",
            "wall_time_s", "contact_solve_s", "Q_over_muP", "a", "c_over_a", "c_over_a_theory",
            "c_over_a_error"]
    write_csv("friction.csv", keys, rows)


if __name__ == "__main__":
    main()
