#!/usr/bin/env python3
"""Cattaneo-Mindlin on uniform, graded and adaptive meshes (doc/friction.md,
section 5.5): the errors of c/a and of the tangential traction t in L2
against the unknowns, dd-newton, exact contact, the pressure in load step 1
and the shear in step 2 (prm/cattaneo_mindlin.prm).

- uniform: the scene's 8 x 4 cells per block refined globally r times;
- graded: the scene's mesh, its refinement box (the zone) refined r times
  (the a-priori grading of tests/cattaneo_mindlin.cc);
- adaptive: 8 x 4 cells with the box refined 3 times, then the nested loop
  of Adaptation/Mode = nested on both blocks, in every load step (the slip
  history moves with the mesh), up to Max cycles per step, with Kelly's
  estimator (gradient jumps only) or the residual estimator (traction
  jumps, the whole contact traction as Neumann data, cell residual), or
  the scaled FEM-BEM estimator (whose BEM is loaded by the same traction).

The reference is Cattaneo-Mindlin at the computed force: a and p0 of Hertz
at P, c = a sqrt(1 - Q/(mu P)), and t(x) = mu p0/a (sqrt(a^2 - x^2) -
sqrt(c^2 - x^2)) for |x| < c, mu p(x) in the slip zones. The L2 error of t
is taken over the contact points with their weights, relative to the L2
norm of the reference. The finite blocks make a about 0.7 % narrower than
Hertz's (tests/hertz.cc), which bounds how far the errors can fall.

Writes doc/friction-adaptivity.csv.

    scripts/friction_adaptivity_study.py [build/ddcontact]   (a Release build)
"""
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from friction_study import (fit_zero_of_root, read_profile, study_box,  # noqa: E402
                            write_csv)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "ddcontact")
SCENE = os.path.join(ROOT, "prm", "cattaneo_mindlin.prm")
# prm/cattaneo_mindlin.prm
R, E, NU, MU = 50.0, 1000.0, 0.3, 0.3
E_STAR = 1.0 / (2.0 * (1.0 - NU * NU) / E)


def mindlin_traction(x, a, p0, c):
    """Cattaneo-Mindlin's tangential traction at x (zero outside a)."""
    if abs(x) >= a:
        return 0.0
    q = MU * p0 / a * math.sqrt(a * a - x * x)
    if abs(x) < c:
        q -= MU * p0 / a * math.sqrt(c * c - x * x)
    return q


def run(kind, level, out, estimator="kelly"):
    settings = ["Contact solver/Solver=dd-newton",
                "Output/Write vtu=false"] + study_box()
    for body in ("upper", "lower"):
        if kind == "uniform":
            settings += [f"Body {body}/Mesh/Box refinement=0",
                         f"Body {body}/Mesh/Initial refinement={level}"]
        elif kind == "graded":
            settings += [f"Body {body}/Mesh/Box refinement={level}"]
        else:
            settings += [f"Body {body}/Mesh/Box refinement=3"]
    if kind == "adaptive":
        settings += ["Adaptation/Mode=nested", "Adaptation/Bodies=upper, lower",
                     f"Adaptation/Estimator={estimator}",
                     "Adaptation/Marking=fraction",
                     "Adaptation/Fraction=0.2", f"Adaptation/Max cycles={level}"]
    args = [EXE, "--output", out, SCENE]
    for s in settings:
        args += ["--set", s]
    subprocess.run(args, capture_output=True, text=True, check=True)
    summary = json.load(open(os.path.join(out, "summary.json")))
    f = read_profile(out)
    x, p, t, w = f["x1"], f["pressure"], f["tangential_traction"], f["weight"]
    state = [int(s) for s in f["state"]]
    P = sum(a * b for a, b in zip(p, w))
    Q = sum(a * b for a, b in zip(t, w))
    a = math.sqrt(4 * P * R / (math.pi * E_STAR))
    p0 = 2 * P / (math.pi * a)
    c = a * math.sqrt(1 - Q / (MU * P))
    stick = [i for i in range(len(x)) if state[i] == 1]
    a_fit = fit_zero_of_root([xi for xi, pi in zip(x, p) if pi > 0],
                             [pi for pi in p if pi > 0])
    c_fit = fit_zero_of_root([x[i] for i in stick],
                             [MU * p[i] - abs(t[i]) for i in stick])
    q = [mindlin_traction(xi, a, p0, c) for xi in x]
    error = math.sqrt(sum(wi * (ti - qi) ** 2 for wi, ti, qi in zip(w, t, q)))
    norm = math.sqrt(sum(wi * qi ** 2 for wi, qi in zip(w, q)))
    theory = math.sqrt(1 - Q / (MU * P))
    return {"mesh": kind, "estimator": estimator if kind == "adaptive" else "",
            "level": level,
            "unknowns": sum(b["dofs"] for b in summary["bodies"]),
            "contact_points": len(x),
            "Q_over_muP": Q / (MU * P),
            "c_over_a": c_fit / a_fit, "c_over_a_theory": theory,
            "c_over_a_error": c_fit / a_fit / theory - 1,
            "t_L2_error": error / norm,
            "newton_steps": summary["newton_steps"],
            "wall_time_s": summary["wall_time_s"]}


def main():
    rows = []
    cases = [("uniform", r, "") for r in (2, 3, 4, 5)] + \
            [("graded", r, "") for r in (4, 5, 6, 7, 8)] + \
            [("adaptive", k, e) for e in ("kelly", "residual", "fem-bem-scaled")
             for k in (2, 4, 6, 8)]
    only = os.environ.get("STUDY_ONLY")  # e.g. "adaptive:residual"
    with tempfile.TemporaryDirectory() as work:
        for kind, level, estimator in cases:
            if only and f"{kind}:{estimator}" != only:
                continue
            row = run(kind, level,
                      os.path.join(work, f"{kind}{estimator}{level}"),
                      estimator or "kelly")
            print(row, flush=True)
            rows.append(row)
    keys = ["mesh", "estimator", "level", "unknowns", "contact_points", "Q_over_muP", "c_over_a",
            "c_over_a_theory", "c_over_a_error", "t_L2_error", "newton_steps",
            "wall_time_s"]
    write_csv("friction-adaptivity.csv", keys, rows)


if __name__ == "__main__":
    main()
