#!/usr/bin/python3
"""Figures of the two study tables that have no plot of their own:

  doc/stability.csv (scripts/stability_matrix.sh)
      -> doc/stability/verdicts.png: the verdicts per case family, and the
         error of every checked case against its tolerance;
  doc/scaling.csv, doc/scaling-memory.csv (scripts/scaling.sh)
      -> doc/scaling/scaling.png: speed-up per phase and peak memory
         against the number of MPI processes.

usage: plot_study_tables.py [SOURCE_DIR]   (default: the repository)

Reads only the CSV files, so the figures are redrawn without rerunning the
studies. Needs matplotlib (Debian: /usr/bin/python3 with python3-matplotlib).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

VERDICT_COLOURS = [("ok", "tab:green"), ("reported", "tab:orange"),
                   ("reference", "0.7"), ("FAIL", "tab:red"),
                   ("WRONG", "tab:purple")]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def save(fig, out_dir, name):
    fig.tight_layout()
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, name)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def verdict(row):
    """The first word of the verdict column: ok, reported, reference,
    FAIL or WRONG."""
    return row["verdict"].split(" ")[0]


def stability(source, out_dir):
    data = rows(os.path.join(source, "doc", "stability.csv"))
    groups = []
    for r in data:
        if r["group"] not in groups:
            groups.append(r["group"])
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.6),
                                 gridspec_kw=dict(width_ratios=[1, 1.3]))

    # Left: stacked bars of the verdicts per family.
    left = [0] * len(groups)
    y = list(range(len(groups)))
    for name, colour in VERDICT_COLOURS:
        counts = [sum(1 for r in data if r["group"] == g and verdict(r) == name)
                  for g in groups]
        if not any(counts):
            continue
        ax.barh(y, counts, left=left, color=colour, edgecolor="k",
                linewidth=0.4, label=f"{name} ({sum(counts)})")
        for i, c in enumerate(counts):
            if c:
                ax.text(left[i] + c / 2, i, str(c), ha="center", va="center",
                        fontsize=8)
        left = [a + b for a, b in zip(left, counts)]
    ax.set_yticks(y)
    ax.set_yticklabels(groups)
    ax.invert_yaxis()
    ax.set_xlabel("number of cases")
    ax.set_title(f"verdicts of the {len(data)} cases")
    ax.legend(fontsize=8, loc="lower right")

    # Right: error / tolerance of every case checked against a reference,
    # by family (all must lie left of 1).
    for i, g in enumerate(groups):
        pts = []
        for r in data:
            if r["group"] != g or verdict(r) != "ok":
                continue
            try:
                err, tol = float(r["error"]), float(r["tol"])
            except ValueError:
                continue
            pts.append(max(err, 1e-17) / tol)
        bx.scatter(pts, [i] * len(pts), s=18, color="tab:green",
                   edgecolor="k", linewidth=0.3, zorder=3)
    bx.axvline(1, color="tab:red", linestyle="--", linewidth=1,
               label="tolerance")
    bx.set_xscale("log")
    bx.set_yticks(y)
    bx.set_yticklabels(groups)
    bx.invert_yaxis()
    bx.set_xlabel("relative error / tolerance (dimensionless)")
    bx.set_title("cases with verdict ok: error against the independent answer")
    bx.grid(True, axis="x", alpha=0.3)
    bx.legend(fontsize=8, loc="lower left")
    fig.suptitle("Stability matrix (doc/stability.csv): no hang, crash, NaN "
                 "or wrong answer")
    return save(fig, out_dir, "verdicts.png")


def scaling(source, out_dir):
    runs = {r["run"]: r for r in rows(os.path.join(source, "doc", "scaling.csv"))}
    memory = rows(os.path.join(source, "doc", "scaling-memory.csv"))
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.6))

    # Left: speed-up of each phase against one process, one thread.
    base = runs["np1_threads1"]
    layouts = [("np1_threads2", "1 process, 2 threads", "s", ":"),
               ("np2_threads1", "2 processes, a body each", "o", "-"),
               ("np2_all", "2 processes, every body on both (MUMPS, p4est)",
                "D", "--")]
    phases = [("wall_s", "whole run", "tab:blue"),
              ("setup_s", "setup", "tab:orange"),
              ("contact_solve_s", "DD iterations", "tab:green"),
              ("body_solves_s", "body solves", "tab:red")]
    for phase, phase_label, colour in phases:
        for run, _, marker, style in layouts:
            r = runs[run]
            procs = int(r["processes"]) + (0.04 if run == "np1_threads2" else 0)
            ax.plot([1, procs], [1, float(base[phase]) / float(r[phase])],
                    marker=marker, linestyle=style, color=colour)
    ax.plot([1, 2], [1, 2], color="k", linewidth=0.8, label="ideal (= processes)")
    # Two legends: the colour is the phase, the line the layout.
    for phase, phase_label, colour in phases:
        ax.plot([], [], color=colour, linewidth=6, label=phase_label)
    for _, label, marker, style in layouts:
        ax.plot([], [], color="0.3", marker=marker, linestyle=style, label=label)
    ax.set_xticks([1, 2])
    ax.set_xlim(0.8, 2.6)
    ax.set_xlabel("MPI processes")
    ax.set_ylabel("speed-up against 1 process, 1 thread (time ratio)")
    ax.set_title(f"strong scaling, {int(base['dofs']):,} dofs, "
                 f"{base['dd_iterations']} DD iterations")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")

    # Right: peak memory against processes, shared against distributed.
    styles = {"serial": ("k", "o"), "shared": ("tab:blue", "s"),
              "distributed": ("tab:green", "D")}
    serial = [m for m in memory if m["mesh"] == "serial"][0]
    for m in memory:
        if m["mesh"] == "serial":
            continue
        colour, marker = styles[m["mesh"]]
        for key, style, what in (
                ("peak_memory_largest_process_mb", "-", "peak, largest process"),
                ("peak_memory_all_processes_mb", "--", "peak, all processes"),
                ("mesh_memory_largest_process_mb", ":",
                 "mesh, dofs, constraints per process")):
            bx.plot([1, int(m["processes"])],
                    [float(serial[key]), float(m[key])], color=colour,
                    marker=marker, linestyle=style,
                    label=f"{m['mesh']} meshes: {what}")
    bx.annotate("1 process: serial meshes, UMFPACK", (1, float(serial[
        "peak_memory_largest_process_mb"])), xytext=(1.05, 1200), fontsize=7,
        arrowprops=dict(arrowstyle="->", linewidth=0.6))
    bx.set_yscale("log")
    bx.set_xticks([1, 2])
    bx.set_xlim(0.8, 2.2)
    bx.set_xlabel("MPI processes")
    bx.set_ylabel("memory [MB]")
    bx.set_title(f"memory, {int(serial['dofs']):,} dofs, every body on "
                 "every process")
    bx.grid(True, which="both", alpha=0.3)
    bx.legend(fontsize=7, loc="center right")
    fig.suptitle("Runs on several MPI processes (doc/scaling.csv, "
                 "doc/scaling-memory.csv)")
    return save(fig, out_dir, "scaling.png")


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..")
    print(stability(source, os.path.join(source, "doc", "stability")))
    print(scaling(source, os.path.join(source, "doc", "scaling")))


if __name__ == "__main__":
    main()
