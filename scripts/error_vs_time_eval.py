#!/usr/bin/env python3
"""Evaluation half of scripts/error_vs_time.sh (standard library only, so
that the quick mode runs on any python3, without numpy or matplotlib).

  error_vs_time_eval.py reference RUNS OUT_JSON OUT_PROFILE_CSV
      Builds the reference of the benchmark from the monolithic degree-2 runs
      in RUNS (p2_c<c>_r<r>/): Richardson extrapolation in h for the penalised
      problem of the scene (c = 0.05), and, for exact contact, extrapolation
      in the penalty c -> 0 of the h-extrapolated values at c = 0.05, 0.025,
      0.0125.

  error_vs_time_eval.py energy-reference RUNS REF_JSON
      Replaces the energy F of the penalised problem in REF_JSON by the limit
      of the nested adaptive degree-2 runs p2_adaptive_c<n>/ (Aitken's
      extrapolation along the sequence), checked against the uniform value.

  error_vs_time_eval.py floor RUNS OUT_CSV
      Collects the single-body runs floor_<celltype>_p<deg>_r<r>/ into a table
      of (cell type, degree, dofs, setup + solve time).

  error_vs_time_eval.py evaluate MANIFEST RUNS REF_JSON REF_PROFILE FLOOR_CSV OUT_CSV [TARGETS_MD]
      One row per run of the manifest (name, series, problem, omega1 degree,
      omega2 degree, setting): time (the median over the run's repeats
      NAME.rep<k>/), unknowns, the relative errors against the reference of
      the problem the run solves, the estimator's effectivity, and the ratio
      of the run's wall time to the floor; TARGETS_MD gets the table of the
      targets of doc/error-vs-time.md. Exit status 1 if a run has no
      summary, did not converge, its repeats disagree, or an error is not
      finite.

doc/error-vs-time.md explains the measures.
"""
import csv
import json
import math
import os
import sys

PENALTY_C = ["0.05", "0.025", "0.0125"]
QUANTITIES = ["u1", "u2", "max_pressure", "half_width", "force", "E1", "E2",
              "J", "F"]


# ---------------------------------------------------------------- reading
def read_summary(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f)


def read_profile(run_dir):
    """(x1, pressure, weight) along S_1, sorted by x1."""
    rows = []
    with open(os.path.join(run_dir, "contact_S.csv")) as f:
        for r in csv.DictReader(f):
            rows.append((float(r["x1"]), float(r["pressure"]),
                         float(r["weight"])))
    rows.sort()
    return rows


def quantities(run_dir):
    """The scalar results of one run; F = E1 + E2 + J is the energy
    functional of the penalised problem (15), J = theta/2 int p^2 the
    penalty energy (the pressure is -sigma_n = -(1/theta)(f_n - u_1n - u_2n)^-)."""
    s = read_summary(run_dir)
    prof = read_profile(run_dir)
    theta = s["theta"][0]
    c = s["contact"][0]
    q = {
        "u1": s["points"][0]["u"][0],
        "u2": s["points"][0]["u"][1],
        "max_pressure": c["max_pressure"],
        "half_width": c["half_width"],
        "force": math.hypot(*c["force"][0]),
        "E1": s["bodies"][0]["strain_energy"],
        "E2": s["bodies"][1]["strain_energy"],
        "J": 0.5 * theta * sum(w * p * p for _, p, w in prof),
    }
    q["F"] = q["E1"] + q["E2"] + q["J"]
    return q, prof


# ---------------------------------------------------------------- reference
def richardson(values):
    """Three values on meshes h, h/2, h/4 -> (extrapolated, uncertainty,
    observed order). Monotone convergence: Richardson with the observed order,
    uncertainty = the size of the correction. Otherwise (oscillating, e.g. a
    quantity quantised by the contact points): the finest value, uncertainty
    = the largest of the last two changes."""
    q0, q1, q2 = values
    d1, d2 = q1 - q0, q2 - q1
    if d2 != 0 and d1 / d2 > 1.2:
        ratio = d1 / d2
        correction = d2 / (ratio - 1.0)
        return q2 + correction, abs(correction), math.log2(ratio)
    if d2 == 0 and d1 == 0:
        return q2, 0.0, float("nan")
    return q2, max(abs(d1), abs(d2)), float("nan")


def extrapolate_penalty(v):
    """Values at c, c/2, c/4 -> the limit c -> 0: quadratic through the three,
    uncertainty |quadratic - linear through the two smallest c|."""
    quad = (8.0 * v[2] - 6.0 * v[1] + v[0]) / 3.0
    lin = 2.0 * v[2] - v[1]
    return quad, abs(quad - lin)


def interpolate(profile, x):
    """Linear interpolation of a sorted (x, p, ...) profile; 0 outside."""
    lo, hi = 0, len(profile) - 1
    if x <= profile[0][0] or x >= profile[-1][0]:
        return 0.0
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if profile[mid][0] <= x:
            lo = mid
        else:
            hi = mid
    x0, p0 = profile[lo][0], profile[lo][1]
    x1, p1 = profile[hi][0], profile[hi][1]
    return p0 + (p1 - p0) * (x - x0) / (x1 - x0) if x1 > x0 else p0


def make_reference(runs, out_json, out_profile):
    def run(c, r):
        return os.path.join(runs, "p2_c%s_r%d" % (c, r))

    ref = {"penalty": {}, "exact": {}, "runs": {}}
    # Penalised problem of the scene (c = 0.05): levels 3, 4, 5.
    levels = {"0.05": [3, 4, 5], "0.025": [2, 3, 4], "0.0125": [2, 3, 4]}
    per_c = {}
    for c in PENALTY_C:
        vals = [quantities(run(c, r))[0] for r in levels[c]]
        for r, v in zip(levels[c], vals):
            s = read_summary(run(c, r))
            ref["runs"]["p2_c%s_r%d" % (c, r)] = dict(
                v, dofs=[b["dofs"] for b in s["bodies"]],
                wall_time_s=s["wall_time_s"])
        per_c[c] = {}
        for k in QUANTITIES:
            e, u, order = richardson([v[k] for v in vals])
            per_c[c][k] = (e, u, order)
    for k in QUANTITIES:
        e, u, order = per_c["0.05"][k]
        ref["penalty"][k] = {"value": e, "uncertainty": u,
                             "observed_order": order}
    # Exact contact: the h-extrapolated values at three penalties, c -> 0.
    # The Richardson uncertainties at each c are propagated with the
    # weights of the quadratic extrapolation (8/3, 2, 1/3).
    for k in QUANTITIES:
        if k == "J":
            continue
        v = [per_c[c][k][0] for c in PENALTY_C]
        uh = [per_c[c][k][1] for c in PENALTY_C]
        e, uc = extrapolate_penalty(v)
        uprop = math.sqrt((uh[0] / 3) ** 2 + (2 * uh[1]) ** 2 +
                          (8 * uh[2] / 3) ** 2)
        ref["exact"][k] = {"value": e, "uncertainty": uc + uprop,
                           "penalty_values": v}
    ref["exact"]["J"] = {"value": 0.0, "uncertainty": 0.0}
    # Pressure profiles: the finest c = 0.05 run (penalty) and the pointwise
    # c -> 0 extrapolation of the finest runs at the three penalties (exact),
    # on the points of the finest c = 0.05 run.
    pen = read_profile(run("0.05", 5))
    finest = [read_profile(run(c, levels[c][-1])) for c in PENALTY_C]
    rows = []
    for x, p, w in pen:
        v = [interpolate(f, x) for f in finest]
        rows.append((x, p, max(0.0, extrapolate_penalty(v)[0]), w))
    with open(out_profile, "w") as f:
        f.write("x1,pressure_penalty,pressure_exact,weight\n")
        for r in rows:
            f.write("%.12g,%.12g,%.12g,%.12g\n" % r)
    for name in ("penalty", "exact"):
        i = 1 if name == "penalty" else 2
        p2 = sum(r[3] * r[i] ** 2 for r in rows)
        ref[name]["pressure_L2"] = math.sqrt(p2)
    ref["theta"] = read_summary(run("0.05", 5))["theta"][0]
    with open(out_json, "w") as f:
        json.dump(ref, f, indent=2)
        f.write("\n")
    for name in ("penalty", "exact"):
        print(name)
        for k in QUANTITIES:
            r = ref[name][k]
            print("  %-13s %.9g +- %.2g" % (k, r["value"], r["uncertainty"]))


def aitken(f0, f1, f2):
    """The limit of a geometrically converging sequence from three terms."""
    d1, d2 = f1 - f0, f2 - f1
    if d1 == 0 or d2 == 0 or d2 / d1 >= 1:
        return f2
    r = d2 / d1
    return f2 + d2 * r / (1 - r)


def make_energy_reference(runs, ref_json):
    """F of the penalised problem from the nested adaptive degree-2 runs:
    along the sequence F_h - F ~ N^-2 (the estimator's optimal rate), the
    successive changes shrink by a nearly constant factor (~0.5), so
    Aitken's Delta^2 of the last three runs is the limit; the uncertainty
    is the largest change of that extrapolation over the last three triples.
    The uniform degree-2 value must agree within the two uncertainties."""
    with open(ref_json) as f:
        ref = json.load(f)
    names = sorted((d for d in os.listdir(runs)
                    if d.startswith("p2_adaptive_c") and
                    os.path.isdir(os.path.join(runs, d))),
                   key=lambda d: int(d[len("p2_adaptive_c"):]))
    seq = []
    for d in names:
        q = quantities(os.path.join(runs, d))[0]
        s = read_summary(os.path.join(runs, d))
        seq.append({"run": d, "dofs": sum(b["dofs"] for b in s["bodies"]),
                    "F": q["F"], "E1": q["E1"], "E2": q["E2"],
                    "estimate": s.get("relative_energy_error_estimate"),
                    "wall_time_s": s["wall_time_s"]})
    if len(seq) < 5:
        print("energy-reference: need at least 5 adaptive runs, found %d" %
              len(seq), file=sys.stderr)
        return 1
    F = [r["F"] for r in seq]
    ext = [aitken(*F[i - 2:i + 1]) for i in range(2, len(F))]
    value = ext[-1]
    unc = max(abs(ext[-1] - ext[-2]), abs(ext[-2] - ext[-3]))
    pen = ref["penalty"]
    uniform = pen["F"].get("uniform_p2", {
        "value": pen["F"]["value"], "uncertainty": pen["F"]["uncertainty"],
        "observed_order": pen["F"].get("observed_order")})
    # Effectivity of the FEM-BEM estimate along the sequence, against the
    # relative energy-norm error of both bodies it estimates:
    # ||e||_A / ||u||_A <= sqrt((F_h - F) / (E_1 + E_2)).
    for r in seq:
        exact = math.sqrt(max(r["F"] - value, 0.0) / (r["E1"] + r["E2"]))
        r["effectivity"] = (r["estimate"] / exact
                            if exact > 0 and r["estimate"] else None)
    pen["F"] = {"value": value, "uncertainty": unc,
                "method": "Aitken extrapolation of nested adaptive P2/Q2 "
                          "(FEM-BEM, Doerfler 0.5) monolithic runs",
                "uniform_p2": uniform, "sequence": seq}
    with open(ref_json, "w") as f:
        json.dump(ref, f, indent=2)
        f.write("\n")
    print("%-18s %9s %18s %10s %8s" % ("run", "dofs", "F", "estimate",
                                        "effect."))
    for r in seq:
        print("%-18s %9d %18.13f %10.3e %8s" % (
            r["run"], r["dofs"], r["F"], r["estimate"] or float("nan"),
            "%.3f" % r["effectivity"] if r["effectivity"] else "-"))
    res = math.sqrt(unc / pen["E2"]["value"])
    print("F = %.13f +- %.2g (energy measure resolved to %.1e); uniform P2: "
          "%.13f +- %.2g" % (value, unc, res, uniform["value"],
                             uniform["uncertainty"]))
    if abs(value - uniform["value"]) > unc + uniform["uncertainty"]:
        print("energy-reference: the adaptive and uniform values disagree",
              file=sys.stderr)
        return 1
    return 0


# ---------------------------------------------------------------- floor
def make_floor(runs, out_csv):
    rows = []
    for d in sorted(os.listdir(runs)):
        if not d.startswith("floor_") or not os.path.isdir(
                os.path.join(runs, d)):
            continue
        _, cell, deg, _ = d.split("_")
        s = read_summary(os.path.join(runs, d))
        t = s["timings"]
        rows.append((cell, int(deg[1:]), s["bodies"][0]["dofs"],
                     t.get("setup", 0.0) + t.get("solve", 0.0)))
    with open(out_csv, "w") as f:
        f.write("cell_type,degree,dofs,setup_plus_solve_s\n")
        for r in sorted(rows):
            f.write("%s,%d,%d,%.6g\n" % r)


def read_floor(path):
    curves = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            key = (r["cell_type"], int(r["degree"]))
            curves.setdefault(key, []).append(
                (int(r["dofs"]), float(r["setup_plus_solve_s"])))
    for k in curves:
        curves[k].sort()
    return curves


def floor_time(curve, dofs):
    """Log-log interpolation of one factorization + solve against dofs;
    beyond the ends the last segment's slope."""
    if len(curve) == 1:
        return curve[0][1] * dofs / curve[0][0]
    i = 1
    while i < len(curve) - 1 and curve[i][0] < dofs:
        i += 1
    (n0, t0), (n1, t1) = curve[i - 1], curve[i]
    t0, t1 = max(t0, 1e-6), max(t1, 1e-6)
    s = math.log(t1 / t0) / math.log(n1 / n0)
    return t0 * math.exp(s * math.log(dofs / n0))


# ---------------------------------------------------------------- Hertz
def hertz_constants(run_dir):
    """E*, R of prm/hertz.prm as used by the run (parameters.prm): the two
    bodies' E and nu, and the constant R of the gap x^2 / (2R)."""
    E, nu, R = [], [], None
    with open(os.path.join(run_dir, "parameters.prm")) as f:
        for line in f:
            t = line.split("#")[0].strip()
            if t.startswith("set Young's modulus"):
                E.append(float(t.split("=")[1]))
            elif t.startswith("set Poisson's ratio"):
                nu.append(float(t.split("=")[1]))
            elif t.startswith("set Constants"):
                for kv in t.split("=", 1)[1].split(","):
                    k, v = kv.split("=")
                    if k.strip() == "R":
                        R = float(v)
    e_star = 1.0 / sum((1 - n * n) / e for e, n in zip(E, nu))
    return e_star, R


def hertz_errors(run_dir, q, prof):
    """Closed form (doc/verification.md §2.2) at the computed force P: a = sqrt(4PR/(pi E*)),
    p0 = sqrt(P E* / (pi R)). The computed half-width is the least-squares
    fit of p^2 = p0^2 (1 - x^2/a^2) over the points in contact (as in
    doc/contact-dd.md), or the largest |x| in contact where fewer than two
    distinct |x| are; the peak pressure is max_pressure; the profile error
    is the L2 distance to p0 sqrt(1 - x^2/a^2)."""
    e_star, R = hertz_constants(run_dir)
    P = q["force"]
    a = math.sqrt(4 * P * R / (math.pi * e_star))
    p0 = math.sqrt(P * e_star / (math.pi * R))
    pts = [(x * x, p * p) for x, p, _ in prof if p > 0]
    n = len(pts)
    sx = sum(t for t, _ in pts); sy = sum(v for _, v in pts)
    sxx = sum(t * t for t, _ in pts); sxy = sum(t * v for t, v in pts)
    den = n * sxx - sx * sx
    # Fewer than two distinct |x| in contact (a coarse mesh with exact
    # contact: one point each side) cannot fit a line; the half-width is
    # then the active set's, known only to the point spacing.
    a_fit = max((math.sqrt(t) for t, _ in pts), default=float("nan"))
    if len({round(t, 12) for t, _ in pts}) >= 2 and den != 0:
        B = (n * sxy - sx * sy) / den
        A = (sy - B * sx) / n
        if B < 0 and A > 0:
            a_fit = math.sqrt(-A / B)

    def exact(x):
        return p0 * math.sqrt(1 - x * x / (a * a)) if abs(x) < a else 0.0

    num = sum(w * (p - exact(x)) ** 2 for x, p, w in prof)
    den2 = p0 * p0 * 4.0 * a / 3.0    # int_{-a}^{a} p0^2 (1 - x^2/a^2) dx
    return {"err_max_pressure": relative(q["max_pressure"], p0),
            "err_half_width": relative(a_fit, a),
            "err_pressure_L2": math.sqrt(num / den2),
            "hertz_a": a, "hertz_p0": p0, "a_fit": a_fit}


# ---------------------------------------------------------------- evaluate
def relative(a, b):
    return abs(a - b) / abs(b)


HEADER = ["name", "series", "problem", "setting", "status",
          "wall_time_s", "repeats", "time_min_s", "time_max_s", "floor_s",
          "time_over_floor", "dofs_omega1",
          "dofs_omega2", "dofs", "bem_unknowns", "cells_omega2",
          "dd_iterations", "uzawa_updates", "u1", "u2", "max_pressure",
          "half_width", "force", "E2", "F", "err_u", "err_u1", "err_u2",
          "err_max_pressure", "err_half_width", "err_force",
          "err_pressure_L2", "err_energy", "err_energy_both",
          "estimate", "effectivity", "bem_s", "bem_over_floor",
          "err_u_vs_exact"]


def check(row, failures):
    """A run counts as failed if it did not converge or one of its errors
    is not finite (None: no reference for that measure)."""
    if row["status"] != "converged":
        failures.append("%s: status %s" % (row["name"], row["status"]))
    for k in HEADER:
        if k.startswith("err_") and row.get(k) is not None and \
                not math.isfinite(row[k]):
            failures.append("%s: %s = %s" % (row["name"], k, row[k]))


def hertz_row(name, series, setting, s, q, prof, d, failures):
    """prm/hertz.prm runs: errors against the closed form; the measures
    without one (u, force, energy) stay empty. The time is not compared
    with a floor (no single-body curve for these meshes)."""
    h = hertz_errors(d, q, prof)
    dofs = [b["dofs"] for b in s["bodies"]]
    row = {k: None for k in HEADER}
    row.update({
        "name": name, "series": series, "problem": "hertz",
        "setting": setting, "status": s.get("status", "?"),
        "dofs_omega1": dofs[0],
        "dofs_omega2": dofs[1], "dofs": dofs[0] + dofs[1],
        "cells_omega2": s["bodies"][1]["cells"],
        "dd_iterations": s.get("dd_iterations", 0),
        "uzawa_updates": s.get("uzawa_updates", 0),
        "u1": q["u1"], "u2": q["u2"], "max_pressure": q["max_pressure"],
        "half_width": h["a_fit"], "force": q["force"], "E2": q["E2"],
        "F": q["F"], "err_max_pressure": h["err_max_pressure"],
        "err_half_width": h["err_half_width"],
        "err_pressure_L2": h["err_pressure_L2"]})
    row["wall_time_s"], row["repeats"], row["time_min_s"], \
        row["time_max_s"] = repeated_timing(os.path.dirname(d), name, q,
                                            failures)
    check(row, failures)
    return row


def reach(rows, level, measure="err_energy"):
    """When a series reaches an error level: the first run (by median time)
    from which every later run stays at or below it -- a lucky crossing
    does not count -- and the time and unknowns interpolated log-log
    between that run and the one before it. None if never."""
    rows = sorted(rows, key=lambda r: r["wall_time_s"])
    i = len(rows)
    while i > 0 and rows[i - 1][measure] is not None and \
            rows[i - 1][measure] <= level:
        i -= 1
    if i == len(rows):
        return None
    hit = rows[i]
    t, n = hit["wall_time_s"], hit["dofs"]
    if i > 0:
        a = rows[i - 1]
        s = math.log(level / a[measure]) / math.log(hit[measure] / a[measure])
        t = a["wall_time_s"] * (hit["wall_time_s"] / a["wall_time_s"]) ** s
        n = a["dofs"] * (hit["dofs"] / a["dofs"]) ** s
    return {"run": hit["name"], "time": hit["wall_time_s"],
            "dofs": hit["dofs"], "time_interp": t, "dofs_interp": n}


# The targets of the benchmark (doc/error-vs-time.md): which series are
# compared at which energy-norm level.
TARGETS = [
    ("degree 1, 1 %", 1e-2, ["fembem-scaled-combined-doerfler-P1",
                             "fembem-scaled-nested-doerfler-P1"],
     "uniform-", "-P1", "kelly-"),
    ("degree 2, 0.1 %", 1e-3, ["fembem-scaled-combined-doerfler-P2",
                               "fembem-scaled-nested-doerfler-P2"],
     "uniform-", "-P2", "kelly-"),
]


def write_targets(out, path):
    """Time and unknowns at which each penalty series reaches 1 % and 0.1 %
    energy-norm error, and the factors the targets ask for."""
    series = {}
    for r in out:
        if r["problem"] == "penalty":
            series.setdefault(r["series"], []).append(r)
    lines = ["| series | level | first run there | median time [s] | dofs "
             "| interpolated time [s] | interpolated dofs |",
             "| --- | ---: | --- | ---: | ---: | ---: | ---: |"]
    hits = {}
    for level in (1e-2, 1e-3):
        for name in sorted(series):
            h = reach(series[name], level)
            hits[(name, level)] = h
            if h:
                lines.append("| %s | %g | %s | %.3g | %d | %.3g | %.0f |" % (
                    name, level, h["run"], h["time"], h["dofs"],
                    h["time_interp"], h["dofs_interp"]))
            else:
                lines.append("| %s | %g | not reached | | | | |" % (name,
                                                                  level))
    lines += ["", "| target | adaptive series | time [s] | best uniform "
              "(same degree) | time [s] | uniform / adaptive (first run; "
              "interpolated) | dofs: uniform / adaptive | Kelly | time [s] "
              "| adaptive / Kelly |",
              "| --- | --- | ---: | --- | ---: | ---: | ---: | --- | ---: "
              "| ---: |"]

    def best(prefix, suffix, level):
        c = [(hits[(n, level)]["time"], n) for n in series
             if n.startswith(prefix) and n.endswith(suffix)
             and hits.get((n, level))]
        return min(c) if c else None

    for label, level, adaptive, uprefix, suffix, kprefix in TARGETS:
        u = best(uprefix, suffix, level)
        k = best(kprefix, suffix, level) if kprefix else None
        for name in adaptive:
            h = hits.get((name, level))
            if not h:
                lines.append("| %s | %s | not reached | | | | | | | |" % (
                    label, name))
                continue
            cells = [label, name, "%.3g" % h["time"]]
            if u:
                hu = hits[(u[1], level)]
                cells += [u[1], "%.3g" % hu["time"], "%.2f; %.2f" % (
                    hu["time"] / h["time"],
                    hu["time_interp"] / h["time_interp"]),
                    "%.1f" % (hu["dofs"] / h["dofs"])]
            else:
                cells += ["not reached", "", "", ""]
            if k:
                cells += [k[1], "%.3g" % k[0], "%.2f" % (h["time"] / k[0])]
            else:
                cells += ["-", "", ""]
            lines.append("| " + " | ".join(cells) + " |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


def bem_cost(run_dir, summary, curves, degrees):
    """The run's BEM time (assembly and factorization, solves, interior
    stresses) and its ratio to the floor summed over the meshes the BEM
    checked (one factorization + solve of each body per estimated cycle of
    statistics.csv): the target "the BEM costs no more than the FEM
    factorization and solve it checks"."""
    t = summary["timings"]
    bem = sum(v for k, v in t.items() if k.startswith("BEM"))
    path = os.path.join(run_dir, "statistics.csv")
    if bem == 0 or not os.path.isfile(path):
        return None, None
    fem = 0.0
    with open(path) as f:
        for r in csv.DictReader(f):
            if r.get("estimated") == "1":
                fem += (floor_time(curves[("triangle", degrees[0])],
                                   int(r["dofs_omega1"])) +
                        floor_time(curves[("quadrilateral", degrees[1])],
                                   int(r["dofs_omega2"])))
    return bem, (bem / fem if fem > 0 else None)


def repeated_timing(runs, name, q, failures):
    """Median, minimum and maximum wall time over the run and its repeats
    NAME.rep<k>; the repeats must give the same answer (the code is
    deterministic for a fixed thread count)."""
    times = [read_summary(os.path.join(runs, name))["wall_time_s"]]
    k = 2
    while os.path.isfile(os.path.join(runs, "%s.rep%d" % (name, k),
                                      "summary.json")):
        d = os.path.join(runs, "%s.rep%d" % (name, k))
        times.append(read_summary(d)["wall_time_s"])
        qk = quantities(d)[0]
        if any(qk[x] != q[x] and relative(qk[x], q[x]) > 1e-12
               for x in ("u1", "u2", "force", "E1", "E2")):
            failures.append("%s: repeat %d gives another answer" % (name, k))
        k += 1
    times.sort()
    n = len(times)
    median = times[n // 2] if n % 2 else 0.5 * (times[n // 2 - 1] +
                                               times[n // 2])
    return median, n, times[0], times[-1]


def evaluate(manifest, runs, ref_json, ref_profile, floor_csv, out_csv,
             targets_md=None):
    with open(ref_json) as f:
        ref = json.load(f)
    profile = {"penalty": [], "exact": []}
    with open(ref_profile) as f:
        for r in csv.DictReader(f):
            profile["penalty"].append((float(r["x1"]),
                                       float(r["pressure_penalty"])))
            profile["exact"].append((float(r["x1"]),
                                     float(r["pressure_exact"])))
    curves = read_floor(floor_csv)
    failures = []
    header = HEADER
    out = []
    with open(manifest) as f:
        entries = [l.rstrip("\n").split("|") for l in f if l.strip()]
    for name, series, problem, deg1, deg2, setting in entries:
        d = os.path.join(runs, name)
        try:
            s = read_summary(d)
            q, prof = quantities(d)
        except (OSError, ValueError, KeyError, IndexError) as e:
            failures.append("%s: no result (%s)" % (name, e))
            continue
        if problem == "hertz":
            out.append(hertz_row(name, series, setting, s, q, prof, d,
                                 failures))
            continue
        R = ref[problem]
        v = {k: R[k]["value"] for k in QUANTITIES}
        if problem == "exact":
            # Exact contact: the functional is the strain energy alone (the
            # constraint replaces the penalty term; the Uzawa multiplier
            # carries no energy).
            q["F"] = q["E1"] + q["E2"]
        e1 = relative(q["u1"], v["u1"])
        e2 = relative(q["u2"], v["u2"])
        # Pressure profile: L2 over S of (p_h - p_ref) on the run's own
        # contact quadrature, relative to the L2 norm of p_ref.
        pr = profile[problem]
        num = sum(w * (p - interpolate(pr, x)) ** 2 for x, p, w in prof)
        err_p = math.sqrt(num) / R["pressure_L2"]
        # Energy: 2 (F_h - F) >= ||u_h - u||_A^2 >= ||u_h - u||_{a_2}^2 for the
        # Galerkin solution of the penalised problem with exact Dirichlet
        # data, so sqrt(|F_h - F| / E2) bounds the relative energy-norm error
        # of Omega_2 (||u_2||_{a_2}^2 = 2 E2).
        err_e = math.sqrt(abs(q["F"] - v["F"]) / v["E2"])
        # The same bound relative to both bodies' energy norm, which the
        # FEM-BEM estimate (relative_energy_error_estimate) estimates.
        err_both = math.sqrt(abs(q["F"] - v["F"]) / (v["E1"] + v["E2"]))
        estimate = s.get("relative_energy_error_estimate")
        if not isinstance(estimate, float) or not math.isfinite(estimate):
            estimate = None
        wall, repeats, tmin, tmax = repeated_timing(runs, name, q, failures)
        bem, bem_ratio = bem_cost(d, s, curves, (int(deg1), int(deg2)))
        dofs = [b["dofs"] for b in s["bodies"]]
        floor = (floor_time(curves[("triangle", int(deg1))], dofs[0]) +
                 floor_time(curves[("quadrilateral", int(deg2))], dofs[1]))
        row = {
            "name": name, "series": series, "problem": problem,
            "setting": setting, "status": s.get("status", "?"),
            "wall_time_s": wall, "repeats": repeats, "time_min_s": tmin,
            "time_max_s": tmax, "floor_s": floor,
            "time_over_floor": wall / floor,
            "dofs_omega1": dofs[0], "dofs_omega2": dofs[1],
            "dofs": dofs[0] + dofs[1],
            "bem_unknowns": s.get("bem_unknowns", 0),
            "cells_omega2": s["bodies"][1]["cells"],
            "dd_iterations": s.get("dd_iterations", 0),
            "uzawa_updates": s.get("uzawa_updates", 0),
            "u1": q["u1"], "u2": q["u2"], "max_pressure": q["max_pressure"],
            "half_width": q["half_width"], "force": q["force"],
            "E2": q["E2"], "F": q["F"],
            "err_u": max(e1, e2), "err_u1": e1, "err_u2": e2,
            "err_max_pressure": relative(q["max_pressure"],
                                         v["max_pressure"]),
            "err_half_width": relative(q["half_width"], v["half_width"]),
            "err_force": relative(q["force"], v["force"]),
            "err_pressure_L2": err_p, "err_energy": err_e,
            "err_energy_both": err_both if problem == "penalty" else None,
            "estimate": estimate, "bem_s": bem, "bem_over_floor": bem_ratio,
            "effectivity": (estimate / err_both if estimate and
                            problem == "penalty" and err_both > 0 else None),
            "err_u_vs_exact": max(relative(q["u1"], ref["exact"]["u1"]["value"]),
                                  relative(q["u2"], ref["exact"]["u2"]["value"])),
        }
        check(row, failures)
        out.append(row)
    with open(out_csv, "w") as f:
        w = csv.writer(f)
        w.writerow(header)
        for r in out:
            w.writerow([("%.6g" % r[k]) if isinstance(r[k], float) else
                        ("" if r[k] is None else r[k]) for k in header])
    print("%-34s %8s %8s %9s %9s %9s %9s %9s %9s %9s" % (
        "run", "time[s]", "t/floor", "err_u", "err_pmax", "err_a",
        "err_P", "err_pL2", "err_E", "dofs"))
    def f(v, fmt):
        return (fmt % v) if v is not None else "-"

    for r in out:
        print("%-34s %8.3f %8s %9s %9s %9s %9s %9s %9s %9d" % (
            r["name"], r["wall_time_s"], f(r["time_over_floor"], "%.1f"),
            f(r["err_u"], "%.2e"), f(r["err_max_pressure"], "%.2e"),
            f(r["err_half_width"], "%.2e"), f(r["err_force"], "%.2e"),
            f(r["err_pressure_L2"], "%.2e"), f(r["err_energy"], "%.2e"),
            r["dofs"]))
    if targets_md:
        write_targets(out, targets_md)
    if len(out) != len(entries) or failures:
        for m in failures:
            print("FAILED: " + m, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    cmd = sys.argv[1] if len(sys.argv) > 1 else ""
    if cmd == "reference" and len(sys.argv) == 5:
        make_reference(*sys.argv[2:])
    elif cmd == "energy-reference" and len(sys.argv) == 4:
        sys.exit(make_energy_reference(*sys.argv[2:]))
    elif cmd == "floor" and len(sys.argv) == 4:
        make_floor(*sys.argv[2:])
    elif cmd == "evaluate" and len(sys.argv) in (8, 9):
        sys.exit(evaluate(*sys.argv[2:]))
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
