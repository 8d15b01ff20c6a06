#!/usr/bin/env python3
"""Draw the paper's figures 4, 7, 8, 9 and 10 from the runs of
scripts/paper_reproduction.sh (CSV and summary.json written by ddcontact).

usage: plot_paper_figures.py RUNS_DIR OUT_DIR
       plot_paper_figures.py --from-csv OUT_DIR

The first form draws every figure and writes OUT_DIR/delta_sweep.csv (the
delta sweep with the fine reference) and OUT_DIR/printed_estimator.csv.
Figures 8 and 10 are drawn from delta_sweep.csv alone, so the second form
redraws them from the CSV kept in doc/ without the runs. Lengths and
displacements are in cm, stresses in MPa (the scene's units).
"""
import csv
import glob
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.ticker import (FixedFormatter, FixedLocator,  # noqa: E402
                               NullLocator)

if len(sys.argv) != 3:
    sys.exit(__doc__)
runs, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)


def summary(name):
    with open(os.path.join(runs, name, "summary.json")) as f:
        return json.load(f)


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def cells(path):
    data = rows(path)
    polys = [[(float(r[f"x{i}"]), float(r[f"y{i}"])) for i in range(4)] for r in data]
    return polys, data


def mesh_files(name):
    return sorted(glob.glob(os.path.join(runs, name, "cells_omega2-*.csv")))


def draw_mesh(ax, path, values=None, cmap="viridis"):
    polys, data = cells(path)
    coll = PolyCollection(polys, edgecolors="k", linewidths=0.15,
                          facecolors="none" if values is None else None, cmap=cmap)
    if values is not None:
        coll.set_array([float(r[values]) for r in data])
    ax.add_collection(coll)
    ax.set_xlim(-2, 2)
    ax.set_ylim(0, 1)
    ax.set_aspect("equal")
    ax.set_xlabel("$x_1$ [cm]")
    ax.set_ylabel("$x_2$ [cm]")
    return coll, len(data)


def sweep_figures(path):
    """Fig. 8 and Fig. 10 from delta_sweep.csv (one row per delta, with the
    fine reference in every row)."""
    sweep = [{k: float(v) for k, v in r.items()} for r in rows(path)]
    sweep.sort(key=lambda r: -r["delta"])
    d = [r["delta"] for r in sweep]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, key, label in ((axes[0], "u1", "$u_1$"), (axes[1], "u2", "$u_2$")):
        ax.semilogx(d, [r[key] for r in sweep], "o-", label="combined algorithm")
        ax.axhline(sweep[0][key + "_reference"], color="k", ls="--",
                   label="fine uniform reference")
        # Tick labels at the deltas of the sweep only: the default log
        # labels (2e-1, 1e-1, 6e-2, 4e-2, 3e-2) overlap on this short range.
        ax.xaxis.set_major_locator(FixedLocator(d))
        ax.xaxis.set_major_formatter(FixedFormatter([f"{x:g}" for x in d]))
        ax.xaxis.set_minor_locator(NullLocator())
        ax.ticklabel_format(axis="y", style="sci", scilimits=(0, 0))
        ax.set_xlabel("adaptation threshold $\\delta$ (dimensionless)")
        ax.set_ylabel(label + " at (0.5, 0.75) [cm]")
        ax.invert_xaxis()
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle("Fig. 8: displacement at (0.5, 0.75) against $\\delta$")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig8_point_displacement.png"), dpi=150)

    fig, ax = plt.subplots(figsize=(6, 4.2))
    inv = [1 / r["delta"] for r in sweep]
    ax.loglog(inv, [r["fem"] + r["bem"] for r in sweep], "o-",
              label="adaptive (FEM + BEM)")
    ax.loglog(inv, [r["uniform_fem"] + r["uniform_bem"] for r in sweep], "s--",
              label="uniform, same smallest cell")
    ax.xaxis.set_major_locator(FixedLocator(inv))
    ax.xaxis.set_major_formatter(FixedFormatter([f"{x:.3g}" for x in inv]))
    ax.xaxis.set_minor_locator(NullLocator())
    ax.set_xlabel("$1/\\delta$ (dimensionless)")
    ax.set_ylabel("unknowns M of $\\Omega_2$ (FEM dofs + BEM unknowns)")
    ax.set_title("Fig. 10: unknowns against $1/\\delta$")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig10_unknowns.png"), dpi=150)


if runs == "--from-csv":
    sweep_figures(os.path.join(out, "delta_sweep.csv"))
    print("figures 8 and 10 written to", out)
    sys.exit(0)


# Fig. 4: von Mises stress in Omega_2 (final mesh of the finest delta).
paper = "paper_delta_0.1"
finest = sorted([p for p in glob.glob(os.path.join(runs, "delta_*")) if os.path.isdir(p)], key=lambda p: float(p.split("_")[-1]))[0]
last = mesh_files(os.path.basename(finest))[-1]
fig, ax = plt.subplots(figsize=(9, 2.8))
coll, n = draw_mesh(ax, last, "von_mises", "jet")
fig.colorbar(coll, ax=ax, label="von Mises stress [MPa]")
ax.set_title(f"Fig. 4: von Mises stress in $\\Omega_2$ ({os.path.basename(finest).replace('_', ' = ')}, {n} cells)")
fig.tight_layout()
fig.savefig(os.path.join(out, "fig4_von_mises.png"), dpi=150)

# Fig. 7: meshes of Omega_2 at the start, at adaptation step 3 and at the end.
files = mesh_files(paper)
picks = [(files[0], "start")]
if len(files) > 4:
    picks.append((files[3], "step 3"))
picks.append((files[-1], "end"))
fig, axes = plt.subplots(len(picks), 1, figsize=(9, 2.9 * len(picks)))
for ax, (path, label) in zip(axes, picks):
    _, n = draw_mesh(ax, path)
    ax.set_title(f"{label}: {n} cells")
fig.suptitle("Fig. 7: meshes of $\\Omega_2$, combined algorithm, delta = 0.1")
fig.tight_layout()
fig.savefig(os.path.join(out, "fig7_meshes.png"), dpi=150)

# Fig. 8 and 10: the delta sweep.
reference = summary("reference")
u_ref = reference["points"][0]["u"]
sweep = []
for path in sorted(glob.glob(os.path.join(runs, "delta_*"))):
    if not os.path.isdir(path):
        continue
    name = os.path.basename(path)
    s = summary(name)
    stats = rows(os.path.join(path, "statistics.csv"))
    _, final_cells = cells(mesh_files(name)[-1])
    level = max(int(r["level"]) for r in final_cells)
    omega2 = [b for b in s["bodies"] if b["name"] == "omega2"][0]
    # A uniform mesh of the same smallest cell: the 16 x 4 start mesh
    # refined 'level' times; its BEM grows with the boundary, 2^level times
    # the start mesh's.
    nx, ny = 16 * 2**level, 4 * 2**level
    uniform_fem = 2 * (nx + 1) * (ny + 1)
    uniform_bem = int(stats[0]["bem_unknowns"]) * 2**level
    sweep.append(dict(delta=float(name.split("_")[1]), u1=s["points"][0]["u"][0],
                      u2=s["points"][0]["u"][1], cells=omega2["cells"],
                      fem=omega2["dofs"], bem=s["bem_unknowns"], level=level,
                      uniform_fem=uniform_fem, uniform_bem=uniform_bem,
                      cycles=s["adaptation_cycles"], dd=s["dd_iterations"],
                      wall=s["wall_time_s"], u1_reference=u_ref[0],
                      u2_reference=u_ref[1]))
sweep.sort(key=lambda r: -r["delta"])
with open(os.path.join(out, "delta_sweep.csv"), "w") as f:
    w = csv.DictWriter(f, fieldnames=list(sweep[0].keys()))
    w.writeheader()
    w.writerows(sweep)
sweep_figures(os.path.join(out, "delta_sweep.csv"))

# Fig. 9: contact displacement and pressure along S for every iteration k,
# with the converged fine pressure as the reference line.
profiles = sorted(glob.glob(os.path.join(runs, paper, "contact_S_*.csv")))
ref_profile = rows(os.path.join(runs, "reference", "contact_S.csv"))
fig, axes = plt.subplots(1, 2, figsize=(11, 4))
cmap = plt.get_cmap("viridis")
for i, path in enumerate(profiles):
    k = int(os.path.basename(path).split("_")[-1].split(".")[0])
    p = rows(path)
    x = [float(r["x1"]) for r in p]
    colour = cmap(i / max(1, len(profiles) - 1))
    axes[0].plot(x, [float(r["u_2n"]) for r in p], color=colour, lw=1, label=f"k = {k}")
    axes[1].plot(x, [float(r["pressure"]) for r in p], color=colour, lw=1, label=f"k = {k}")
axes[1].plot([float(r["x1"]) for r in ref_profile], [float(r["pressure"]) for r in ref_profile],
             "k--", lw=1.5, label="converged, fine mesh")
axes[0].set_ylabel("contact displacement $u_{2n}$ of $\\Omega_2$ [cm]")
axes[1].set_ylabel("contact pressure $\\sigma_n^* = -\\sigma_n$ [MPa]")
for ax in axes:
    ax.set_xlabel("$x_1$ [cm]")
    ax.legend(fontsize=7)
fig.suptitle("Fig. 9: iterations of the combined algorithm (gamma = 0.02, eps_u = 0.0015, delta = 0.1)")
fig.tight_layout()
fig.savefig(os.path.join(out, "fig9_contact_iterations.png"), dpi=150)

# The printed estimator (27): marked cells per cycle.
stats = rows(os.path.join(runs, "printed_delta_0.1", "statistics.csv"))
with open(os.path.join(out, "printed_estimator.csv"), "w") as f:
    f.write("cycle,cells,marked,eta_max\n")
    for r in stats:
        f.write(f"{r['cycle']},{r['cells_omega2']},{r['marked']},{r['eta_max']}\n")

print("figures written to", out)
