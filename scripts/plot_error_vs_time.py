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
    ("err_energy", "energy-norm error, sqrt(|F_h - F| / E_2)", "F"),
    # Both contact measures at once: the target of adaptive exact contact
    # (issue 30), max(err_force, err_max_pressure).
    ("err_force_and_peak", "contact force and peak pressure, the larger "
     "error", None),
]
LEVELS = [1e-2, 1e-3, 1e-4]
# The rows of each figure: the strategies whose series name starts with the
# prefix.
FAMILIES = [("uniform meshes (monolithic Newton and DD)", "uniform"),
            ("adapted by Kelly", "kelly"),
            ("adapted by the FEM-BEM estimator", "fembem"),
            ("Hertz scene, against the closed form", "hertz")]


def style(series):
    """Colour by strategy (family and mode), marker by degree (circle P1,
    diamond P2, square exact contact), dashes for the paper's fixed gamma,
    dots for the compliance-optimal gamma."""
    colors = [("uniform-monolithic", "black"), ("uniform-DDnewton", "tab:cyan"),
              ("uniform-DD", "tab:blue"), ("kelly-nested", "tab:green"),
              ("kelly-combined", "tab:olive"), ("fembem-printed", "tab:red"),
              ("fembem-scaled-nested", "tab:purple"),
              ("fembem-scaled-combined-doerfler", "tab:pink"),
              ("fembem-scaled-combined-threshold", "tab:brown"),
              ("hertz-DD-newton", "tab:cyan"), ("hertz", "tab:blue")]
    color = next((c for k, c in colors if series.startswith(k)), "tab:grey")
    ls = "--" if "fixed" in series else (":" if "auto" in series else "-")
    marker = "s" if "exact" in series else ("D" if series.endswith("P2")
                                            else "o")
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
    if measure == "err_force_and_peak":
        return max(R[k]["uncertainty"] / abs(R[k]["value"])
                   for k in ("force", "max_pressure"))
    if key is None:
        return float("nan")
    return R[key]["uncertainty"] / abs(R[key]["value"])


def draw_series(ax, rs, name, measure, x, label, **extra):
    """One strategy's runs, in run order (growing meshes), so that a run
    faster than a coarser one shows as a step back."""
    pts = [(r[x], max(r[measure], 1e-9)) for r in rs]
    kw = style(name)
    kw.update(extra)
    ax.loglog([p[0] for p in pts], [p[1] for p in pts], label=label, **kw)


def plot_measure(series, ref, measure, title, key, out_dir):
    """One figure per error measure: a row of two panels (against wall time
    and against unknowns) per family of strategies, each with its own
    legend, so that no legend has more than eight entries; the adaptive rows
    repeat the uniform P1 and P2 baselines in grey for comparison."""
    drawn = {}
    for name, rs in series.items():
        rs = [r for r in rs if isinstance(r[measure], float)]
        if rs:
            drawn[name] = sorted(rs, key=lambda r: (r["dofs"], r["wall_time_s"]))
    rows = [(label, [n for n in drawn if n.startswith(prefix)])
            for label, prefix in FAMILIES]
    rows = [(label, names) for label, names in rows if names]
    fig, axes = plt.subplots(len(rows), 2, figsize=(13, 3.3 * len(rows) + 0.8),
                             sharex="col", sharey=True, squeeze=False)
    baselines = [("uniform-monolithic-P1", "0.75"),
                 ("uniform-DD-anderson-P2", "0.55")]
    for (family, names), row in zip(rows, axes):
        for name in names:
            label = name + {"exact": " [vs exact]", "hertz": " [vs Hertz]"}.get(
                drawn[name][0]["problem"], "")
            for ax, x in zip(row, ("wall_time_s", "dofs")):
                draw_series(ax, drawn[name], name, measure, x,
                            label if x == "dofs" else None)
        for baseline, grey in baselines:
            if baseline in drawn and not family.startswith("uniform") \
                    and drawn[names[0]][0]["problem"] == "penalty":
                for ax, x in zip(row, ("wall_time_s", "dofs")):
                    draw_series(ax, drawn[baseline], baseline, measure, x,
                                baseline + " (for comparison)"
                                if x == "dofs" else None,
                                color=grey, linewidth=2.5, zorder=0)
        for ax in row:
            for lv in LEVELS:
                ax.axhline(lv, color="0.8", linewidth=0.8, zorder=0)
            u = reference_floor(ref, "penalty", key, measure)
            if math.isfinite(u) and u > 0 and not family.startswith("Hertz"):
                ax.axhline(u, color="tab:red", linewidth=0.8, linestyle=":")
            ax.grid(True, which="major", alpha=0.3)
        row[0].set_ylabel("relative error\n(dimensionless)")
        row[0].set_title(family, loc="left", fontsize=10)
        row[1].legend(fontsize=8, loc="center left", bbox_to_anchor=(1.02, 0.5))
    axes[-1][0].set_xlabel("wall time [s] (summary.json wall_time_s)")
    axes[-1][1].set_xlabel("unknowns (FEM dofs of both bodies, count)")
    for ax in axes[-1]:
        ax.tick_params(labelbottom=True)
    fig.suptitle("%s (red dotted: reference uncertainty)" % title)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, measure[4:] + ".png"), dpi=110)
    plt.close(fig)


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
            both = (r.get("err_force"), r.get("err_max_pressure"))
            r["err_force_and_peak"] = (max(both) if all(
                isinstance(e, float) for e in both) else "")
            rows.append(r)
    series = {}
    for r in rows:
        series.setdefault(r["series"], []).append(r)

    for measure, title, key in MEASURES:
        plot_measure(series, ref, measure, title, key, out_dir)

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
            if problem == "penalty" and measure == "err_force_and_peak":
                continue
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
