#!/usr/bin/env python3
"""The table of doc/contact-solvers.md section 3 from doc/contact-solvers.csv
(scripts/contact_solver_study.sh), in Markdown on standard output:

  scripts/contact_solver_table.py [CSV]

Per scene and penalty c, for the meshes h and h/8 (refinement 0 and 3):
dd-newton's body-solve sets, Newton steps and CG iterations; the relative
difference of its force from the monolithic solver's on h/8; the DD's
(Anderson) iterations; the monolithic solver's Newton steps. A run stopped
with a message (exit 4) shows "stop" (with its sets or iterations), a run
killed after 120 s (exit 124) "> 120 s".
"""
import csv
import sys


def load(path):
    runs = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (row["scene"], row["c"], row["refinement"], row["solver"])
            runs[key] = row
    return runs


def cell(run, field, with_count):
    if run is None:
        return "-"
    if run["exit"] == "124":
        return ">120 s"
    if run["exit"] != "0":
        return "stop (%s)" % run[field] if with_count else "stop"
    return run[field]


def pair(runs, scene, c, solver, field, with_count=False):
    return " / ".join(cell(runs.get((scene, c, r, solver)), field, with_count)
                      for r in ("0", "3"))


def force_difference(runs, scene, c):
    a = runs.get((scene, c, "3", "dd-newton"))
    b = runs.get((scene, c, "3", "monolithic"))
    if a is None or b is None or a["exit"] != "0" or b["exit"] != "0":
        return "-"
    return "%.1e" % (abs(float(a["force"]) - float(b["force"])) /
                     float(b["force"]))


def main():
    runs = load(sys.argv[1] if len(sys.argv) > 1 else "doc/contact-solvers.csv")
    scenes, penalties = [], []
    for scene, c, _, _ in runs:
        if scene not in scenes:
            scenes.append(scene)
        if c not in penalties:
            penalties.append(c)
    print("| scene | c | dd-newton body-solve sets, h / h/8 | Newton steps "
          "| CG iterations | force: dd-newton vs monolithic, h/8 "
          "| DD (Anderson) iterations | monolithic Newton steps |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for scene in scenes:
        for c in penalties:
            print("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
                scene, c,
                pair(runs, scene, c, "dd-newton", "body_solve_sets", True),
                pair(runs, scene, c, "dd-newton", "newton_steps"),
                pair(runs, scene, c, "dd-newton", "krylov_iterations"),
                force_difference(runs, scene, c),
                pair(runs, scene, c, "dd", "body_solve_sets", True),
                pair(runs, scene, c, "monolithic", "newton_steps")))


if __name__ == "__main__":
    main()
