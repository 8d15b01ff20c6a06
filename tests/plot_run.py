"""DESCRIPTION: scripts/plot_run.py draws the output directory of a run: a
Hertz run (VTU written) gives contact_S.png with the Hertz curve,
convergence.png and mesh.png (read from the VTU); a coarse adaptive run of
the paper's scene gives adaptation.png and no Hertz curve (its contact is
a quarter of the zone, no half-plane); a directory that is not a run is
refused in one line with exit code 1. Skipped (exit 77) without matplotlib.

usage: plot_run.py DDCONTACT_EXECUTABLE SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

SKIP = 77
failures = 0


def check(ok, what):
    global failures
    print(("ok:     " if ok else "FAILED: ") + what)
    failures += 0 if ok else 1


def python_with_matplotlib():
    """This interpreter, or Debian's (where python3-matplotlib lives), if
    it can import matplotlib."""
    for exe in (sys.executable, "/usr/bin/python3"):
        if exe and os.path.exists(exe) and subprocess.run(
                [exe, "-c", "import matplotlib"], capture_output=True).returncode == 0:
            return exe
    return None


def is_png(path):
    """Exists, is not empty and starts with the PNG signature."""
    if not os.path.isfile(path) or os.path.getsize(path) < 1000:
        return False
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


def run_scene(exe, scene, out, overrides):
    command = [exe, scene, "--output", out]
    for o in overrides:
        command += ["--set", o]
    result = subprocess.run(command, capture_output=True, text=True)
    check(result.returncode == 0, f"ddcontact {os.path.basename(scene)} ran "
          f"(exit {result.returncode}{': ' + result.stderr.strip() if result.returncode else ''})")


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    exe, source, work = sys.argv[1:]
    python = python_with_matplotlib()
    if python is None:
        print("matplotlib is missing: test skipped")
        return SKIP
    plot = [python, os.path.join(source, "scripts", "plot_run.py")]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    # 1. Hertz, coarse (box refinement 5: about 30 points in contact), with
    #    VTU; the plots go to --out.
    hertz = os.path.join(work, "hertz")
    run_scene(exe, os.path.join(source, "prm", "hertz.prm"), hertz,
              ["Body upper/Mesh/Box refinement=5",
               "Body lower/Mesh/Box refinement=5"])
    pictures = os.path.join(work, "hertz_png")
    result = subprocess.run(plot + [hertz, "--out", pictures], capture_output=True,
                            text=True)
    print(result.stdout + result.stderr)
    check(result.returncode == 0, "plot_run.py on the Hertz run: exit 0")
    for name in ("contact_S.png", "convergence.png", "mesh.png"):
        check(is_png(os.path.join(pictures, name)), f"Hertz run: {name} written")
    check("pair S: Hertz curve drawn" in result.stdout,
          "Hertz run: the Hertz curve is drawn")
    check(not os.path.exists(os.path.join(pictures, "adaptation.png")),
          "Hertz run (fixed meshes): no adaptation.png")

    # 2. The paper's scene, coarse, two adaptation cycles at most, no VTU:
    #    the mesh comes from cells_omega2-NNNN.csv.
    paper = os.path.join(work, "paper")
    run_scene(exe, os.path.join(source, "prm", "paper_two_bodies.prm"), paper,
              ["Adaptation/Max cycles=2", "Output/Write vtu=false",
               "Domain decomposition/Relaxation=anderson"])
    result = subprocess.run(plot + [paper, "--units", "cm,MPa"],
                            capture_output=True, text=True)
    print(result.stdout + result.stderr)
    check(result.returncode == 0, "plot_run.py on the paper run: exit 0")
    for name in ("contact_S.png", "convergence.png", "adaptation.png", "mesh.png"):
        check(is_png(os.path.join(paper, name)), f"paper run: {name} written")
    check("pair S: Hertz curve not drawn" in result.stdout,
          "paper run: no Hertz curve (contact too wide for a half-plane)")

    # 3. Not a run: one line on stderr, exit 1.
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    for directory in (empty, os.path.join(work, "missing")):
        result = subprocess.run(plot + [directory], capture_output=True, text=True)
        lines = result.stderr.strip().splitlines()
        check(result.returncode == 1 and len(lines) == 1 and
              lines[0].startswith("plot_run.py: error:"),
              f"{os.path.basename(directory)}: refused in one line "
              f"({result.stderr.strip()})")

    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
