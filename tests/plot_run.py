"""DESCRIPTION: scripts/plot_run.py draws the output directory of a run: a
Hertz run (VTU written) gives contact_S.png with the Hertz curve of a whole
model (the cylinder's, forces per unit thickness), convergence.png titled
dd-newton and mesh.png (read from the VTU); a Cattaneo-Mindlin run adds the
tangential traction with its partial-slip curve, force_displacement.png and
a convergence plot titled monolithic; sheared and then partly unloaded, the
curve is Mindlin-Deresiewicz's from the turning force (its stick zone meets
the computed one within a cell); pressed and sheared together with
Steps = auto (the normal force changing under the shear) it draws no
closed form and says why, and load_path.png with the run's accepted steps
and splits; a synthetic press-then-shear directory whose press step carries
a tangential force of 0.1 % of mu P (0.03 % of P) and whose shear comes in
80 steps of 0.6 % of mu P keeps the Cattaneo-Mindlin curve, one whose
normal force grows by 5 % under the shear is refused; the axisymmetric
sphere prm/hertz_sphere.prm gets Hertz's sphere at its ring force (a and
p0 of hertz_S.json = the closed form at the CSV's force and R = 50, a
within a cell of the computed contact radius, p0 within 2 % of the peak),
also under --symmetry half and full, and its forces labelled as totals over
the ring; a pin in a plate hole (tests/pin_in_hole.prm, a closed contact
curve) is drawn against the arc length, which follows the circle; the Hertz
half model prm/hertz_force.prm is found to be a half model and its curve
takes the whole force 2P (a and p0 of hertz_S.json within 1 % of the closed
form at P = 2 q R, a = 0.149, p0 = 8.18), and --symmetry full gives the
curve of P itself (a smaller by sqrt(2)); a coarse adaptive run of the
paper's scene gives adaptation.png, a convergence plot titled Neumann
domain decomposition and no Hertz curve (its contact is a quarter of the
zone, no half-plane); a directory that is not a run is refused in one line
with exit code 1. Skipped (exit 77) without matplotlib.

usage: plot_run.py DDCONTACT_EXECUTABLE SOURCE_DIR WORK_DIR
"""
import csv
import json
import math
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


def read_json(path):
    """The object in a JSON file, {} when it is missing or not JSON."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def read_csv_rows(path):
    """The rows of a CSV file as dicts of floats."""
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


# Run by the interpreter with matplotlib (and numpy): the abscissa that
# scripts/plot_run.py gives the points of a contact CSV, and what the test
# checks of it.
PROBE = """
import json, math, sys
sys.path.insert(0, sys.argv[1])
import plot_run
points = plot_run.read_csv(sys.argv[2])
label, _ = plot_run.zone_abscissa(points)
points.sort(key=lambda p: p["s"])
angle = [math.atan2(p["x2"], p["x1"]) for p in points]
turns = [(b - a) % (2 * math.pi) for a, b in zip(angle, angle[1:])]
contact = [p["s"] for p in points if p["pressure"] > 0]
print(json.dumps({"label": label,
                  "backward_steps": len(turns) - max(
                      sum(1 for d in turns if 0 < d < 1),
                      sum(1 for d in turns if d > 2 * math.pi - 1)),
                  "span": points[-1]["s"] - points[0]["s"],
                  "contact_half_arc": (max(contact) - min(contact)) / 2}))
"""


# Runs scripts/plot_run.py's main() as the command line does (arguments
# from sys.argv[3:], its stdout and exit code) and writes the texts of
# every figure it saves (suptitle, and each panel's title, axis labels and
# legend) to the JSON file sys.argv[2], {png name: [text, ...]}.
LABELS = """
import json, sys
sys.path.insert(0, sys.argv[1])
import plot_run
texts, save = {}, plot_run.Plotter.save
def recording_save(self, fig, name):
    found = [getattr(fig, "_suptitle", None)]
    for ax in fig.axes:
        found += [ax.title, ax.xaxis.label, ax.yaxis.label]
        legend = ax.get_legend()
        found += legend.get_texts() if legend else []
    texts[name] = [t.get_text() for t in found if t is not None and t.get_text()]
    save(self, fig, name)
plot_run.Plotter.save = recording_save
code = plot_run.main(sys.argv[3:])
with open(sys.argv[2], "w") as f:
    json.dump(texts, f)
sys.exit(code)
"""


def plot_with_labels(python, source, work, args):
    """scripts/plot_run.py ARGS through LABELS: (the completed process,
    {png name: [the figure's texts]})."""
    path = os.path.join(work, "labels.json")
    if os.path.exists(path):
        os.remove(path)
    result = subprocess.run([python, "-c", LABELS, os.path.join(source, "scripts"),
                             path] + args, capture_output=True, text=True)
    print(result.stdout + result.stderr)
    return result, read_json(path)


def mentions(texts, name, words):
    """Whether the texts of figure @p name hold every one of @p words."""
    joined = "\n".join(texts.get(name, []))
    return all(w in joined for w in words)


def write_synthetic_mindlin(directory, press_q, drift, n_shear=80):
    """An output directory that scripts/plot_run.py takes for a
    Cattaneo-Mindlin run, made here from the closed forms: two similar
    blocks (E = 1000, nu = 0.3, mu = 0.3), the gap x^2/(2R) (R = 50) on 400
    points of weight 0.01 over [-2, 2], Hertz's pressure of a = 0.3 in
    every step; step 1 presses with a tangential force press_q mu P
    (traction proportional to p), steps 2 to n_shear + 1 shear to Q = mu
    P/2 in equal parts (Cattaneo-Mindlin's traction at each Q) while the
    normal force grows from (1 - drift) P to P. Returns (P, Q) of the last
    step as the CSV integrates them."""
    os.makedirs(directory)
    mu, radius, e, nu, a = 0.3, 50.0, 1000.0, 0.3, 0.3
    e_star = e / (2 * (1 - nu * nu))
    force = math.pi * a * a * e_star / (4 * radius)
    p0 = 2 * force / (math.pi * a)
    xs = [-2 + 0.01 * (i + 0.5) for i in range(400)]

    def rows(scale, q):
        c = a * math.sqrt(1 - abs(q) / (mu * force))
        out = []
        for x in xs:
            p = scale * p0 * math.sqrt(max(0., 1 - x * x / (a * a)))
            t = (mu * scale * p0 / a * (math.sqrt(max(0., a * a - x * x)) -
                                        math.sqrt(max(0., c * c - x * x))))
            gap = x * x / (2 * radius)
            closure = min(gap, a * a / (2 * radius)) / 2
            out.append([x, 0, p, closure, closure, gap, 0.01, t, 0, 0,
                        1 if abs(x) < c else 2 if p > 0 else 0])
        return out

    def write(name, data):
        with open(os.path.join(directory, name), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["x1", "x2", "pressure", "u_1n", "u_2n", "gap", "weight",
                        "tangential_traction", "slip_increment", "slip",
                        "state"])
            w.writerows(data)

    press = rows(1 - drift, 0.)
    press_p = sum(r[2] * r[6] for r in press)
    for r in press:  # a small tangential force along the pressure
        r[7] = press_q * mu * r[2] * force / press_p
    write("contact_S_step0001.csv", press)
    for k in range(1, n_shear + 1):
        data = rows(1 - drift * (1 - k / n_shear), 0.5 * mu * force * k / n_shear)
        write(f"contact_S_step{k + 1:04d}.csv", data)
    write("contact_S.csv", data)
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump({"status": "converged", "contact": [{"pair": "S"}]}, f)
    prm = ["set Geometry = plane strain", "set Bodies = upper, lower",
           "subsection Contact pair S", "  set Body 1 = upper",
           "  set Body 2 = lower", "  set Friction = coulomb",
           f"  set Friction coefficient = {mu}", "end"]
    for body, corners in (("upper", ("-10, 0", "10, 10")),
                          ("lower", ("-10, -10", "10, 0"))):
        prm += [f"subsection Body {body}", "  subsection Mesh",
                f"    set Corner 1 = {corners[0]}", f"    set Corner 2 = {corners[1]}",
                "  end", "  subsection Material", f"    set Young's modulus = {e}",
                f"    set Poisson's ratio = {nu}", "  end", "end"]
    with open(os.path.join(directory, "parameters.prm"), "w") as f:
        f.write("\n".join(prm) + "\n")
    return (sum(r[2] * r[6] for r in data), sum(r[7] * r[6] for r in data))


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
    result, texts = plot_with_labels(python, source, work,
                                     [hertz, "--out", pictures])
    check(result.returncode == 0, "plot_run.py on the Hertz run: exit 0")
    for name in ("contact_S.png", "convergence.png", "mesh.png"):
        check(is_png(os.path.join(pictures, name)), f"Hertz run: {name} written")
    check("pair S: Hertz curve drawn" in result.stdout,
          "Hertz run: the Hertz curve is drawn")
    check(not os.path.exists(os.path.join(pictures, "adaptation.png")),
          "Hertz run (fixed meshes): no adaptation.png")
    used = read_json(os.path.join(pictures, "hertz_S.json"))
    check(used.get("model") == "full",
          f"Hertz run: taken as a whole model ({used.get('model')}: "
          f"{used.get('model_reason')})")
    check(used.get("geometry") == "plane strain" and
          used.get("closed_form") == "cylinder",
          f"Hertz run: the cylinder's closed form ({used.get('formula')})")
    check(mentions(texts, "contact_S.png", ["force per unit thickness",
                                            "[stress x length]"]) and
          not mentions(texts, "contact_S.png", ["length^2"]) and
          not mentions(texts, "contact_S.png", ["ring"]),
          "Hertz run (plane strain): the force per unit thickness, "
          "[stress x length]")
    check(mentions(texts, "convergence.png", ["dd-newton", "Newton step"]),
          f"Hertz run: convergence.png names dd-newton "
          f"({texts.get('convergence.png', ['?'])[0]})")

    check(not os.path.exists(os.path.join(pictures, "mindlin_S.json")),
          "Hertz run (frictionless): no Cattaneo-Mindlin curve")

    # 1a. Cattaneo-Mindlin (Hertz's blocks, Coulomb, pressed then sheared):
    #     the third panel with t and the partial-slip closed form, c/a =
    #     sqrt(1 - Q/(mu P)) at the run's own Q and P, in (0, 1).
    mindlin = os.path.join(work, "cattaneo_mindlin")
    run_scene(exe, os.path.join(source, "prm", "cattaneo_mindlin.prm"), mindlin,
              ["Body upper/Mesh/Box refinement=5",
               "Body lower/Mesh/Box refinement=5", "Output/Write vtu=false"])
    result, texts = plot_with_labels(python, source, work, [mindlin])
    check(result.returncode == 0 and is_png(os.path.join(mindlin, "contact_S.png")),
          "plot_run.py on the Cattaneo-Mindlin run: contact_S.png written")
    check(mentions(texts, "convergence.png", ["monolithic"]),
          f"Cattaneo-Mindlin run: convergence.png names the monolithic solver "
          f"({texts.get('convergence.png', ['?'])[0]})")
    check(is_png(os.path.join(mindlin, "force_displacement.png")) and
          mentions(texts, "force_displacement.png",
                   ["per unit thickness", "[stress x length]"]),
          "Cattaneo-Mindlin run: force_displacement.png, forces per unit "
          "thickness")
    check(not os.path.exists(os.path.join(mindlin, "load_path.png")),
          "Cattaneo-Mindlin run (two fixed steps, no Check path): no "
          "load_path.png")
    used = read_json(os.path.join(mindlin, "mindlin_S.json"))
    ratio = used.get("c_over_a", float("nan"))
    expected = math.sqrt(1 - abs(used.get("Q", 0)) / (0.3 * used.get("P", 1)))
    check(0 < ratio < 1 and abs(ratio - expected) < 1e-12 and used.get("mu") == 0.3,
          f"Cattaneo-Mindlin curve drawn with mu = 0.3 and c/a = {ratio:.4g}")

    # 1c. Mindlin-Deresiewicz: pressed, sheared to U = 0.0015, then back to
    #     0.0005 (three load steps): the unloading closed form from the
    #     turning force Q* (the second step's) is drawn, not the loading
    #     curve at Q, and its stick zone c' = a sqrt(1 - |Q* - Q|/(2 mu P))
    #     meets the extent of the points that stick in the last step
    #     within a cell of the zone (h = 2.5/2^5), as tests/cattaneo_mindlin.cc
    #     asks of Cattaneo-Mindlin's c (measured 0.006 here, and 6e-4 at
    #     refinement 7, where c' fitted from the stick zone is 0.3 % of a
    #     off).
    unload = os.path.join(work, "mindlin_deresiewicz")
    run_scene(exe, os.path.join(source, "prm", "cattaneo_mindlin.prm"), unload,
              ["Body upper/Mesh/Box refinement=5",
               "Body lower/Mesh/Box refinement=5", "Output/Write vtu=false",
               "Loading/Steps=3",
               "Body upper/Boundary conditions/Dirichlet=3: xy: "
               "0.0015*min(1, max(0, 3*t - 1)) - 0.001*max(0, 3*t - 2); "
               "-Delta*min(1, 3*t)"])
    result = subprocess.run(plot + [unload], capture_output=True, text=True)
    print(result.stdout + result.stderr)
    used = read_json(os.path.join(unload, "mindlin_S.json"))
    steps = [read_csv_rows(os.path.join(unload, f"contact_S_step000{k}.csv"))
             for k in (2, 3)]
    q_star = sum(r["tangential_traction"] * r["weight"] for r in steps[0])
    last = steps[1]
    Q = sum(r["tangential_traction"] * r["weight"] for r in last)
    P = sum(r["pressure"] * r["weight"] for r in last)
    check(result.returncode == 0 and used.get("path") == "reversal" and
          abs(used.get("Q_star", 0) - q_star) <= 1e-9 * abs(q_star),
          f"unloading: the Mindlin-Deresiewicz curve from Q* = {q_star:.4g} "
          f"(the second step's force) to Q = {Q:.4g}")
    expected = math.sqrt(1 - abs(q_star - Q) / (2 * 0.3 * P))
    check(abs(used.get("c_over_a", 0) - expected) < 1e-9,
          f"unloading: c'/a = {used.get('c_over_a', float('nan')):.4g} = "
          f"sqrt(1 - |Q* - Q|/(2 mu P))")
    extent = max(abs(r["x1"]) for r in last if r["state"] == 1)
    h = 2.5 / 2 ** 5
    check(abs(extent - used.get("c", 0)) <= h,
          f"unloading: the stick points reach {extent:.4g}, c' = "
          f"{used.get('c', float('nan')):.4g} (within a cell, {h:.3g})")

    # 1d. Pressed and sheared together, Steps = auto (21 accepted steps and
    #     12 splits at this refinement): the normal force changes under the
    #     shear, so no closed form here; the script says why and removes a
    #     stale record. load_path.png counts the accepted steps of
    #     summary.json's load_steps and the splits of its load_path.
    together = os.path.join(work, "proportional")
    run_scene(exe, os.path.join(source, "prm", "cattaneo_mindlin.prm"), together,
              ["Body upper/Mesh/Box refinement=5",
               "Body lower/Mesh/Box refinement=5", "Output/Write vtu=false",
               "Loading/Steps=auto",
               "Body upper/Boundary conditions/Dirichlet=3: xy: U*t; -Delta*t"])
    with open(os.path.join(together, "mindlin_S.json"), "w") as f:
        f.write("{}\n")
    result, texts = plot_with_labels(python, source, work, [together])
    check(result.returncode == 0 and
          "no Cattaneo-Mindlin curve (the normal force changes" in result.stdout
          and not os.path.exists(os.path.join(together, "mindlin_S.json")),
          "pressed and sheared together: no closed form, and why")
    summary = read_json(os.path.join(together, "summary.json"))
    path = summary.get("load_path", {})
    steps = summary.get("load_steps", [])
    check(path.get("steps") == "auto" and len(steps) > 1 and
          path.get("rejected_steps", 0) > 0,
          f"Steps = auto: {len(steps)} accepted steps, "
          f"{path.get('rejected_steps')} splits")
    check(is_png(os.path.join(together, "load_path.png")) and
          mentions(texts, "load_path.png",
                   [f"{len(steps)} accepted steps",
                    f"{path.get('rejected_steps')} splits",
                    f"{path.get('solves')} solves",
                    f"Path tolerance = {path.get('path_tolerance'):g}"]),
          "Steps = auto: load_path.png with the accepted steps, splits, "
          "solves and the tolerance")

    # 1f. Synthetic press-then-shear runs (written here from the closed
    #     forms, no ddcontact): the press step carries a tangential force
    #     of 0.1 % of mu P (0.03 % of P), the normal force grows by 0.01 %
    #     under the shear, and the shear comes in 80 steps of 0.6 % of
    #     mu P: press-then-shear within the 1 % tolerance, so the
    #     Cattaneo-Mindlin curve at the last Q and P, c/a = sqrt(1 -
    #     Q/(mu P)) (1/sqrt(2) up to the integration over the points).
    #     The same with the normal force growing by 5 % under the shear is
    #     not press-then-shear: no curve.
    synthetic = os.path.join(work, "synthetic_mindlin")
    P, Q = write_synthetic_mindlin(synthetic, 1e-3, 1e-4)
    result = subprocess.run(plot + [synthetic], capture_output=True, text=True)
    print(result.stdout + result.stderr)
    used = read_json(os.path.join(synthetic, "mindlin_S.json"))
    expected = math.sqrt(1 - Q / (0.3 * P))
    check(result.returncode == 0 and used.get("path") == "monotone" and
          abs(used.get("c_over_a", 0) - expected) < 1e-9 and
          abs(expected - math.sqrt(0.5)) < 1e-3,
          f"press step with 0.1 % of mu P: the Cattaneo-Mindlin curve kept, "
          f"c/a = {used.get('c_over_a', float('nan')):.5g} = sqrt(1 - Q/(mu P)) "
          f"= {expected:.5g}")
    drifting = os.path.join(work, "synthetic_drift")
    write_synthetic_mindlin(drifting, 1e-3, 0.05)
    result = subprocess.run(plot + [drifting], capture_output=True, text=True)
    print(result.stdout + result.stderr)
    check(result.returncode == 0 and
          "no Cattaneo-Mindlin curve (the normal force changes" in result.stdout
          and not os.path.exists(os.path.join(drifting, "mindlin_S.json")),
          "normal force growing by 5 % under the shear: no closed form")

    # 1g. Hertz's sphere, axisymmetric (prm/hertz_sphere.prm at box
    #     refinement 6, cells of h = 10/4/2^6 at the contact, pressed in two
    #     steps): the sphere's closed form at the ring force of
    #     contact_S.csv, a = (3 P R/(4 E*))^(1/3), p0 = 3 P/(2 pi a^2),
    #     R = 50, 1/E* = 2 (1 - 0.3^2)/1000; that a is within a cell of the
    #     computed contact radius and p0 within 2 % of the peak pressure
    #     (the cylinder's formula at this force, a = sqrt(4 P R/(pi E*)), is
    #     two cells off, its p0 12 %). --symmetry half or full changes
    #     nothing; the forces say "total over the ring", [stress x
    #     length^2], and never "per unit thickness".
    sphere = os.path.join(work, "hertz_sphere")
    run_scene(exe, os.path.join(source, "prm", "hertz_sphere.prm"), sphere,
              ["Body upper/Mesh/Box refinement=6",
               "Body lower/Mesh/Box refinement=6", "Output/Write vtu=false",
               "Loading/Steps=2",
               "Body upper/Boundary conditions/Dirichlet=3: xy: 0; -Delta*t"])
    result, texts = plot_with_labels(python, source, work, [sphere])
    check(result.returncode == 0 and "pair S: Hertz curve drawn" in result.stdout,
          "sphere: the Hertz curve is drawn")
    used = read_json(os.path.join(sphere, "hertz_S.json"))
    P = sum(r["pressure"] * r["weight"]
            for r in read_csv_rows(os.path.join(sphere, "contact_S.csv")))
    e_star = 1000 / (2 * (1 - 0.3 ** 2))
    a_exact = (3 * P * 50 / (4 * e_star)) ** (1 / 3)
    p0_exact = 3 * P / (2 * math.pi * a_exact ** 2)
    check(used.get("geometry") == "axisymmetric" and
          used.get("closed_form") == "sphere",
          f"sphere: the sphere's closed form ({used.get('formula')})")
    for key, exact in (("a", a_exact), ("p0", p0_exact), ("whole_force", P)):
        value = used.get(key, float("nan"))
        check(abs(value - exact) <= 1e-6 * exact,
              f"sphere: {key} = {value:.6g}, the closed form at the ring force "
              f"{P:.6g} and R = 50: {exact:.6g}")
    contact = read_json(os.path.join(sphere, "summary.json")).get("contact", [{}])[0]
    h = 10 / 4 / 2 ** 6
    check(abs(used.get("a", 0) - contact.get("contact_radius", 0)) <= h,
          f"sphere: a = {used.get('a', float('nan')):.4g} against the computed "
          f"contact radius {contact.get('contact_radius', float('nan')):.4g} "
          f"(a cell, {h:.3g})")
    check(abs(used.get("p0", 0) - contact.get("max_pressure", 0)) <=
          0.02 * contact.get("max_pressure", 0),
          f"sphere: p0 = {used.get('p0', float('nan')):.4g} against the peak "
          f"pressure {contact.get('max_pressure', float('nan')):.4g} (2 %)")
    check(mentions(texts, "contact_S.png", ["ring force", "[stress x length^2]"])
          and not any("per unit thickness" in t for name in texts
                      for t in texts[name]),
          "sphere: the ring force in [stress x length^2], nothing per unit "
          "thickness")
    check(mentions(texts, "force_displacement.png",
                   ["total over the ring", "[stress x length^2]", "axial (z)"]),
          "sphere: force_displacement.png, ring forces against the axial "
          "displacement")
    for option in ("half", "full"):
        out = os.path.join(work, f"hertz_sphere_{option}")
        result = subprocess.run(plot + [sphere, "--symmetry", option, "--out", out],
                                capture_output=True, text=True)
        print(result.stdout + result.stderr)
        other = read_json(os.path.join(out, "hertz_S.json"))
        check(result.returncode == 0 and other.get("closed_form") == "sphere" and
              abs(other.get("a", 0) - used.get("a", 0)) <= 1e-12 * a_exact,
              f"sphere with --symmetry {option}: still the sphere, a = "
              f"{other.get('a', float('nan')):.6g}")

    # 1e. A pin in a plate hole (tests/pin_in_hole.prm): S_1 is the pin's
    #     whole circle, so x1 runs back and forth along it; the profiles are
    #     drawn against the arc length, which must follow the circle (the
    #     angle about the centre grows with it, never back) and span its
    #     polygon (the points lie on chords of faces 0.05 long: the
    #     polygon is 0.2 % shorter than the circle, and the polyline
    #     through the points shorter still by the corners it cuts; 1 %).
    #     The contact arc in s meets summary.json's half_width (half the
    #     arc length of the contact set) within a face.
    pin = os.path.join(work, "pin_in_hole")
    run_scene(exe, os.path.join(source, "tests", "pin_in_hole.prm"), pin,
              ["Output/Write vtu=false"])
    result = subprocess.run(plot + [pin], capture_output=True, text=True)
    print(result.stdout + result.stderr)
    check(result.returncode == 0 and is_png(os.path.join(pin, "contact_S.png")),
          "pin in a hole: contact_S.png written")
    probe = subprocess.run(
        [python, "-c", PROBE, os.path.join(source, "scripts"),
         os.path.join(pin, "contact_S.csv")], capture_output=True, text=True)
    found = json.loads(probe.stdout or "{}") if probe.returncode == 0 else {}
    print(found or probe.stderr)
    summary = read_json(os.path.join(pin, "summary.json"))
    half_width = summary.get("contact", [{}])[0].get("half_width", float("nan"))
    check(found.get("label", "").startswith("arc length") and
          "closed" in found.get("label", ""),
          f"pin in a hole: the axis is the arc length along a closed curve "
          f"({found.get('label')})")
    check(found.get("backward_steps") == 0,
          "pin in a hole: the arc length follows the circle (the angle about "
          "the centre never turns back)")
    check(abs(found.get("span", 0) - 2 * math.pi * 0.98) <= 0.01 * 2 * math.pi * 0.98,
          f"pin in a hole: s spans {found.get('span', float('nan')):.4g}, the "
          f"circle {2 * math.pi * 0.98:.4g} (1 %)")
    check(abs(found.get("contact_half_arc", 0) - half_width) <= 0.05,
          f"pin in a hole: the contact arc in s, {found.get('contact_half_arc', 0):.4g}"
          f" each side, against half_width {half_width:.4g} (a face, 0.05)")

    # 1b. The Hertz half model pressed by a force (quarter cylinder R = 5 on
    #     the right half of a block, rollers u_1 = 0 on x1 = 0): the closed
    #     form at the whole force P = 2 q R, 1/E* = 2 (1 - nu^2)/E.
    q, radius, e, nu = 0.19139, 5.0, 1000.0, 0.3
    whole = 2 * q * radius
    e_star = e / (2 * (1 - nu * nu))
    a_exact = math.sqrt(4 * whole * radius / (math.pi * e_star))
    p0_exact = 2 * whole / (math.pi * a_exact)
    half = os.path.join(work, "hertz_force")
    run_scene(exe, os.path.join(source, "prm", "hertz_force.prm"), half,
              ["Output/Write vtu=false"])
    result = subprocess.run(plot + [half], capture_output=True, text=True)
    print(result.stdout + result.stderr)
    check(result.returncode == 0, "plot_run.py on the half model: exit 0")
    check(is_png(os.path.join(half, "contact_S.png")),
          "half model: contact_S.png written")
    check("pair S: Hertz curve drawn" in result.stdout and "half model" in result.stdout,
          "half model: the Hertz curve is drawn, as a half model")
    used = read_json(os.path.join(half, "hertz_S.json"))
    check(any(line.startswith("hertz S: a = ") for line in result.stdout.splitlines()),
          "half model: the closed form used is printed")
    check(used.get("model") == "half",
          f"half model: detected ({used.get('model')}: {used.get('model_reason')})")
    for key, exact in (("whole_force", whole), ("a", a_exact), ("p0", p0_exact)):
        value = used.get(key, float("nan"))
        check(abs(value - exact) <= 0.01 * exact,
              f"half model: {key} = {value:.5g} against {exact:.5g} "
              f"(the closed form at 2 q R; 1 %)")
    result = subprocess.run(plot + [half, "--symmetry", "full", "--out",
                                    os.path.join(work, "hertz_force_full")],
                            capture_output=True, text=True)
    full = read_json(os.path.join(work, "hertz_force_full", "hertz_S.json"))
    check(result.returncode == 0 and full.get("model") == "full" and
          abs(full.get("a", 0) * math.sqrt(2) - used.get("a", 0))
          <= 1e-9 * a_exact,
          f"--symmetry full: the curve of the half's own force "
          f"(a = {full.get('a', float('nan')):.4g})")

    # 2. The paper's scene, coarse, two adaptation cycles at most, no VTU:
    #    the mesh comes from cells_omega2-NNNN.csv.
    paper = os.path.join(work, "paper")
    run_scene(exe, os.path.join(source, "prm", "paper_two_bodies.prm"), paper,
              ["Adaptation/Max cycles=2", "Output/Write vtu=false",
               "Contact solver/Domain decomposition/Relaxation=anderson"])
    result, texts = plot_with_labels(python, source, work,
                                     [paper, "--units", "cm,MPa"])
    check(result.returncode == 0, "plot_run.py on the paper run: exit 0")
    check(mentions(texts, "convergence.png",
                   ["Neumann domain decomposition", "DD iteration"]),
          f"paper run (dd): convergence.png names the Neumann domain "
          f"decomposition ({texts.get('convergence.png', ['?'])[0]})")
    check(mentions(texts, "contact_S.png", ["per unit thickness", "[MPa cm]"]),
          "paper run: forces per unit thickness in [MPa cm]")
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
