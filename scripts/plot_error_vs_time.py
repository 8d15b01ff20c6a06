#!/usr/bin/python3
"""Plots of scripts/error_vs_time.sh: for each error measure, log-log error
against wall time and against unknowns, one line per strategy; and the
table of the fastest strategy per accuracy level (winners.md).

  plot_error_vs_time.py doc/error-vs-time.csv doc/error-vs-time-reference.json OUT_DIR

Needs matplotlib (Debian: /usr/bin/python3 with python3-matplotlib)."""
import csv
import json
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MEASURES = [
    ("err_u", "displacement at (0.5, 0.75), max of |du_i|/|u_i|", "u1"),
    ("err_max_pressure", "peak contact pressure", "max_pressure"),
    ("err_half_width", "contact half-width (Hertz: fitted a)", "half_width"),
    ("err_force", "total contact force", "force"),
    ("err_pressure_L2", "L2 error of the contact pressure", None),
    ("err_energy", "energy-norm error of Omega_2 (bound)", "F"),
]
LEVELS = [1e-2, 1e-3, 1e-4]


def style(series):
    colors = {"uniform-monolithic-P1": "black", "uniform-monolithic-P2": "grey",
              "uniform-DD": "tab:blue", "kelly-nested": "tab:green",
              "kelly-combined": "tab:olive", "fembem-printed": "tab:red",
              "fembem-scaled": "tab:purple"}
    color = "tab:brown"
    for k, c in colors.items():
        if series.startswith(k):
            color = c
    ls = "--" if "fixed" in series else (":" if "auto" in series else "-")
    marker = "s" if series.endswith("AL") else ("^" if "r4" in series else "o")
    if series == "uniform-monolithic-P2":
        marker = "D"
    return dict(color=color, linestyle=ls, marker=marker, markersize=4,
                linewidth=1.2)


def reference_floor(ref, problem, key, measure):
    """Relative uncertainty of the reference for one measure."""
    if problem not in ref:
        return float("nan")  # Hertz: a closed form
    R = ref[problem]
    if measure == "err_u":
        return max(R["u1"]["uncertainty"] / abs(R["u1"]["value"]),
                   R["u2"]["uncertainty"] / abs(R["u2"]["value"]))
    if measure == "err_energy":
        return math.sqrt(R["F"]["uncertainty"] / R["E2"]["value"])
    if key is None:
        return float("nan")
    return R[key]["uncertainty"] / abs(R[key]["value"])


def time_to_level(rows, measure, level):
    """Earliest wall time from which every run of the series (by time) has
    its error <= level: a lucky single crossing does not count."""
    rows = sorted(rows, key=lambda r: r["wall_time_s"])
    best = None
    for i in range(len(rows) - 1, -1, -1):
        if rows[i][measure] <= level:
            best = rows[i]
        else:
            break
    return best


def main(csv_path, ref_path, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    with open(ref_path) as f:
        ref = json.load(f)
    rows = []
    with open(csv_path) as f:
        for r in csv.DictReader(f):
            for k, v in r.items():
                try:
                    r[k] = float(v)
                except ValueError:
                    pass
            rows.append(r)
    series = {}
    for r in rows:
        series.setdefault(r["series"], []).append(r)

    for measure, title, key in MEASURES:
        fig, axes = plt.subplots(1, 2, figsize=(13, 5.2), sharey=True)
        for name, rs in series.items():
            rs = [r for r in rs if isinstance(r[measure], float)]
            if not rs:
                continue
            rs = sorted(rs, key=lambda r: (r["dofs"], r["wall_time_s"]))
            label = name + {"exact": " [vs exact]", "hertz": " [vs Hertz]"}.get(
                rs[0]["problem"], "")
            for ax, x in zip(axes, ("wall_time_s", "dofs")):
                # In run order (growing meshes), so a run that is faster
                # than a coarser one shows as a step back.
                pts = [(r[x], max(r[measure], 1e-9)) for r in rs]
                ax.loglog([p[0] for p in pts], [p[1] for p in pts],
                          label=label if x == "dofs" else None, **style(name))
        for ax in axes:
            for lv in LEVELS:
                ax.axhline(lv, color="0.8", linewidth=0.8, zorder=0)
            u = reference_floor(ref, "penalty", key, measure)
            if math.isfinite(u) and u > 0:
                ax.axhline(u, color="tab:red", linewidth=0.8, linestyle=":")
            ax.grid(True, which="major", alpha=0.3)
        axes[0].set_xlabel("wall time [s] (summary.json wall_time_s)")
        axes[1].set_xlabel("unknowns (FEM dofs of both bodies)")
        axes[0].set_ylabel("relative error")
        axes[1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.0, 0.5))
        fig.suptitle("%s (red dotted: reference uncertainty)" % title)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, measure[4:] + ".png"), dpi=110)
        plt.close(fig)

    # Winners per level, separately for the penalised problem (the answer)
    # and for exact contact; the last columns name the fastest strategy
    # that uses the DD (everything but the monolithic baselines).
    lines = ["| problem | measure | level | fastest strategy (run) | time [s] | "
             "runner-up (run) | time [s] | factor | fastest DD strategy (run) "
             "| time [s] | DD / fastest |",
             "| --- | --- | ---: | --- | ---: | --- | ---: | ---: | --- | ---: "
             "| ---: |"]
    for problem in ("penalty", "exact", "hertz"):
        for measure, title, key in MEASURES:
            if problem == "hertz" and measure not in (
                    "err_max_pressure", "err_half_width", "err_pressure_L2"):
                continue
            unc = reference_floor(ref, problem, key, measure)
            for lv in LEVELS:
                head = "| %s | %s | %g " % (problem, measure[4:], lv)
                if math.isfinite(unc) and unc > lv / 3:
                    lines.append(head + "| below the reference uncertainty "
                                 "(%.1e) | | | | | | | |" % unc)
                    continue
                hits = []
                for name, rs in series.items():
                    if rs[0]["problem"] != problem:
                        continue
                    if not isinstance(rs[0][measure], float):
                        continue
                    h = time_to_level(rs, measure, lv)
                    if h is not None:
                        hits.append((h["wall_time_s"], name, h["name"]))
                hits.sort()
                dd = [h for h in hits if "monolithic" not in h[1]]
                if not hits:
                    lines.append(head + "| not reached | | | | | | |")
                    continue
                cells = ["%s (%s)" % (hits[0][1], hits[0][2]),
                         "%.3g" % hits[0][0]]
                if len(hits) > 1:
                    cells += ["%s (%s)" % (hits[1][1], hits[1][2]),
                              "%.3g" % hits[1][0],
                              "%.1f" % (hits[1][0] / hits[0][0])]
                else:
                    cells += ["none", "", ""]
                if dd:
                    cells += ["%s (%s)" % (dd[0][1], dd[0][2]),
                              "%.3g" % dd[0][0],
                              "%.1f" % (dd[0][0] / hits[0][0])]
                else:
                    cells += ["not reached", "", ""]
                lines.append(head + "| " + " | ".join(cells) + " |")
    with open(os.path.join(out_dir, "winners.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    main(*sys.argv[1:])
