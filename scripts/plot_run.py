#!/usr/bin/python3
"""Draw the output directory of any ddcontact run.

usage: plot_run.py OUTDIR [--out DIR] [--units LENGTH,STRESS]
                   [--hertz auto|on|off] [--symmetry auto|half|full]
                   [--dpi N]

Writes PNG files into OUTDIR (or DIR), each only when the run wrote what it
needs:
  contact_<pair>.png  per contact pair (contact_<pair>.csv): the pressure
                      -sigma_n along S_1, with the Hertz closed form where it
                      applies (below), and the normal approach u_1n + u_2n
                      against the initial gap f_n; the iterates of
                      contact_<pair>_NNNN.csv in grey when they were written
  hertz_<pair>.json   per pair with the Hertz curve: the closed form used
                      (below); a stale one is removed when no curve is drawn
                      With friction (the CSV's tangential_traction column)
                      a third panel draws the tangential traction t, the
                      Coulomb bound mu p where mu is a number or a constant,
                      and, with the Hertz curve, the closed form of the
                      run's load path (below), recorded in
                      mindlin_<pair>.json
  convergence.png     the contact solver's iteration (history.csv), titled
                      with the solver of summary.json's contact_solver:
                      the Neumann domain decomposition (dd; residual and
                      increment), dd-newton (Newton steps: the Newton
                      residual and the step of the pressure) or the
                      monolithic solver (one row per Newton solve); and the
                      contact force and the largest penetration
  force_displacement.png
                      with load steps (force_displacement.csv): the reaction
                      of every driven Dirichlet id against its mean
                      displacement, per component (against t where no id is
                      driven)
  load_path.png       frictional runs with Loading/Steps = auto (or Check
                      path), from summary.json's load_path and load_steps:
                      t after each accepted step, the step length, and each
                      step's path error against Path tolerance; the splits
                      and solves in the title
  adaptation.png      adaptive runs (statistics.csv): cells and dofs per body,
                      the estimator, marked cells, per adaptation cycle
  mesh.png            the last mesh of every body with its von Mises stress,
                      from the VTU files (read here with the standard
                      library) or, without them, from cells_<body>-NNNN.csv

Geometry: a run is axisymmetric when its parameters.prm says `Geometry =
axisymmetric` (or, without that entry, when summary.json's units say so).
Then x1 is the radius r and x2 the axis z, and every force (contact force,
reaction) is the total over the ring (2 pi r): [stress x length^2]. In plane
strain forces are per unit thickness: [stress x length].

Units: the code takes any consistent system. The axes say "[length]" and
"[stress]" unless --units names them (e.g. --units cm,MPa, the units of the
shipped paper scenes) or summary.json carries a "units" object with
"length" and "stress" entries.

Hertz: with --hertz auto (default) the closed form of doc/verification.md
§2.2 is drawn over a pair's pressure when (a) the initial gap near the
contact is a parabola f = (x - x0)^2 / (2R) (least-squares fit of the gap
column, residual below 2 % of its rise), (b) both bodies' Young's modulus
and Poisson's ratio are in parameters.prm, and (c) the closed-form
half-width a at the computed force is at most a tenth of the contact
zone's length and of the height of a rectangular body (the half-plane
assumption). --hertz on draws it whenever (a) and (b) hold; off never.
Either way the model must be known to be whole or half (below).
The closed form is the geometry's: in plane strain Hertz's cylinder per
unit thickness, a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a); in
axisymmetry Hertz's sphere at the ring's total force P,
a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2), p = p0 sqrt(1 -
r^2/a^2) (doc/axisymmetric.md), 1/E* = sum (1 - nu^2)/E either way. The
sphere's gap is fitted as f = f0 + r^2 / (2R) (even in r: its vertex is on
the axis), the contact must reach the axis, and the size test (c) takes
the zone's radial extent.

Half models: a scene may model only the half x1 >= x0 (or x1 <= x0) of a
Hertz contact, cut on the symmetry line x1 = x0 through the parabola's
vertex and held there by rollers (e.g. prm/hertz_force.prm). Its contact
force P is then that of the half, and the closed form takes the whole
force 2P: a = sqrt(4 (2P) R / (pi E*)), p0 = 2 (2P) / (pi a). With
--symmetry auto (default) a pair is a half model when both
  (i)  its contact zone S_1 ends at the vertex: the vertex x0 of the fitted
       gap parabola is within a tenth of the contact width (the x1-extent
       of the points with positive pressure) of the first or last point of
       contact_<pair>.csv, and that end point is in contact; and
  (ii) a body of the pair has a roller there in parameters.prm: a Dirichlet
       condition on components x only with u_1 = 0 (`ID: x: 0; ...`), on
       a boundary id whose position is not known to the script (a Gmsh
       mesh) or, for a rectangle (ids 0 left, 1 right), at x1 = x0 within
       the same tolerance.
(i) without (ii), a contact that stops at its vertex without a symmetry
condition, is neither model: the curve is not drawn and the message asks
for --symmetry. (ii) without (i), e.g. rollers on the far sides of a whole
model, is a whole model. --symmetry half or full overrides the rule. A half
model's plot says "half model: whole force 2P" in its legend and title and
draws the curve only on the side of the vertex that it models; the half-plane test (c) takes the
whole zone, twice S_1's length. An axisymmetric run is never a half
model: its edge at r = 0 is the axis, and its ring force is the whole
force; --symmetry is ignored there (with a note), so that it cannot turn a
sphere into a plane-strain curve.

For every pair with a curve the script prints one line
  hertz <pair>: a = A, p0 = P0, whole force F (half|full model, R = ...)
(sphere: "... (sphere, axisymmetric, R = ...)") and writes
hertz_<pair>.json with the same numbers (geometry, closed_form "cylinder"
or "sphere" and its formula, model, force of the run's zone, whole force,
R, x0, E*, a, p0, a/L, and why).

The profiles are drawn against x1 on a straight zone (x2 on a vertical
one). On a curved zone x1 may run back and forth (a pin in a hole), so they
are drawn against the arc length s along S_1: the points are chained by
nearest neighbours into the curve (closed or open), s counts from the
point of largest pressure, where it equals that point's x1, and a closed
curve is cut opposite it. The axis label says which and where.

Friction closed forms (Coulomb, elastically similar bodies, a Hertz
curve): the load history comes from contact_<pair>_stepNNNN.csv (or
summary.json's load_steps), the normal force P and the tangential force Q
after each step. A step solves the tangential problem on its final
contact, so the closed forms hold where P stays the same from the first
step that puts Q on; both within 1 % (of mu P for Q, of P for P): a
tangential force below 1 % of mu P (a press step carrying 0.03 % of P,
say) does not count as shear, nor does a reversal of the shear by less,
and P may drift by 1 % under the shear (PATH_TOLERANCE says why 1 %):
  - Q monotone: Cattaneo-Mindlin at the last Q,
      t = mu p0/a (sqrt(a^2 - x^2) - sqrt(c^2 - x^2)),
      c = a sqrt(1 - |Q|/(mu P)) (doc/friction.md §5.2);
  - Q turned once, at Q*, and back toward 0 (Mindlin-Deresiewicz):
      t = t_CM(Q*) - 2 t_CM((Q* - Q)/2), t_CM the curve above for a force,
      with the slip reversed for c' < |x - x0| < a,
      c' = a sqrt(1 - |Q* - Q|/(2 mu P)); once Q has gone past -Q* the
      first loading is forgotten and Cattaneo-Mindlin at Q holds again;
  - otherwise (P changing under the shear, as when pressing and shearing
    together, or Q turning more than once) no curve, and one line saying
    why.
Axisymmetric runs get none: their tangential traction is radial, its ring
integral has no 3D resultant, and a sphere sheared by a force Q is not a
body of revolution's problem.
mindlin_<pair>.json holds Q, P, a, the path, c (c' after a reversal),
c/a, and after a reversal Q* and the loading's c*.

Needs matplotlib (Debian: python3-matplotlib, installed by
scripts/install_deps.sh).
"""
import argparse
import base64
import csv
import glob
import json
import math
import os
import re
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib

PROGRAM = "plot_run.py"


class RunError(Exception):
    """A problem with the run directory, reported in one line."""


# --------------------------------------------------------------------------
# Reading what a run writes


def read_csv(path):
    """Rows of a CSV file as dicts of floats (text kept where not a number)."""
    with open(path, newline="") as f:
        result = []
        for row in csv.DictReader(f):
            converted = {}
            for key, value in row.items():
                try:
                    converted[key] = float(value)
                except (TypeError, ValueError):
                    converted[key] = value
            result.append(converted)
        return result


def read_prm(path):
    """The entries of a deal.II parameter file as {"Section/Entry": value}."""
    entries, stack = {}, []
    if not os.path.isfile(path):
        return entries
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                stack.append(line[len("subsection "):].strip())
            elif line == "end":
                if stack:
                    stack.pop()
            elif line.startswith("set ") and "=" in line:
                key, value = line[4:].split("=", 1)
                entries["/".join(stack + [key.strip()])] = value.strip()
    return entries


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


class Run:
    """The files of one output directory."""

    def __init__(self, directory):
        if not os.path.isdir(directory):
            raise RunError(f"{directory}: no such directory")
        self.directory = directory
        markers = ["summary.json", "history.csv", "statistics.csv"]
        if not any(os.path.isfile(self.path(m)) for m in markers) and \
                not glob.glob(self.path("contact_*.csv")):
            raise RunError(f"{directory} is not the output directory of a "
                           "ddcontact run (no summary.json, history.csv, "
                           "statistics.csv or contact_*.csv)")
        self.summary = {}
        if os.path.isfile(self.path("summary.json")):
            try:
                with open(self.path("summary.json")) as f:
                    self.summary = json.load(f)
            except (OSError, ValueError) as e:
                raise RunError(f"{self.path('summary.json')}: not readable "
                               f"JSON ({e})")
        self.parameters = read_prm(self.path("parameters.prm"))

    def path(self, name):
        return os.path.join(self.directory, name)

    @property
    def axisymmetric(self):
        """Whether the run is axisymmetric: its parameters.prm's Geometry,
        or for a directory without that file summary.json's units text
        (which says "axisymmetric" there)."""
        geometry = self.parameters.get("Geometry")
        if geometry is not None:
            return geometry.strip() == "axisymmetric"
        units = self.summary.get("units")
        return isinstance(units, str) and "axisymmetric" in units

    @property
    def solver(self):
        """The contact solver's name ("dd", "dd-newton", "monolithic"), or
        None where the run does not say."""
        return (self.summary.get("contact_solver") or
                self.parameters.get("Contact solver/Solver"))

    def rows(self, name):
        """The rows of a CSV file of the run ([] when it is missing)."""
        path = self.path(name)
        return read_csv(path) if os.path.isfile(path) else []

    def pair_names(self):
        """The contact pairs, from summary.json or else from the files."""
        names = [c["pair"] for c in self.summary.get("contact", [])
                 if isinstance(c, dict) and "pair" in c]
        if names:
            return names
        found = []
        for path in sorted(glob.glob(self.path("contact_*.csv"))):
            name = os.path.basename(path)[len("contact_"):-len(".csv")]
            if not re.search(r"_\d{4}$", name):
                found.append(name)
        return found

    def constant(self, text):
        """A number, or the value of a name in the scene's Constants."""
        value = number(text)
        if value is not None:
            return value
        for item in self.parameters.get("Constants", "").split(","):
            name, _, v = item.partition("=")
            if name.strip() == (text or "").strip():
                return number(v)
        return None

    def material(self, body):
        e = number(self.parameters.get(f"Body {body}/Material/Young's modulus"))
        nu = number(self.parameters.get(f"Body {body}/Material/Poisson's ratio"))
        return (e, nu) if e and nu is not None else None

    def rectangle_height(self, body):
        prefix = f"Body {body}/Mesh/"
        if self.parameters.get(prefix + "Type", "rectangle") != "rectangle":
            return None
        try:
            y1 = float(self.parameters[prefix + "Corner 1"].split(",")[1])
            y2 = float(self.parameters[prefix + "Corner 2"].split(",")[1])
        except (KeyError, IndexError, ValueError):
            return None
        return abs(y2 - y1)

    def rollers(self, body):
        """The rollers u_1 = 0 of a body: [(boundary id, x1 of the line or
        None where the script cannot know it, or False for a line that is
        not x1 = const)], from its Dirichlet entry `ID: x: 0; ... | ...`."""
        prefix = f"Body {body}/"
        text = self.parameters.get(prefix + "Boundary conditions/Dirichlet", "")
        sides = {}
        if self.parameters.get(prefix + "Mesh/Type", "rectangle") == "rectangle":
            try:
                x1 = float(self.parameters[prefix + "Mesh/Corner 1"].split(",")[0])
                x2 = float(self.parameters[prefix + "Mesh/Corner 2"].split(",")[0])
                sides = {"0": min(x1, x2), "1": max(x1, x2), "2": False,
                         "3": False}
            except (KeyError, IndexError, ValueError):
                sides = {}
        found = []
        for entry in text.split("|"):
            parts = [t.strip() for t in entry.split(":")]
            if len(parts) != 3 or parts[1] != "x":
                continue
            values = [v.strip() for v in parts[2].split(";")]
            if number(values[0]) != 0:
                continue
            found.append((parts[0], sides.get(parts[0])))
        return found


# --------------------------------------------------------------------------
# VTU (deal.II's XML unstructured grid, ascii or zlib-compressed base64)


def decode_data_array(element, dtype, header_type, compressed):
    """The numbers of one DataArray element."""
    text = (element.text or "").strip()
    fmt = element.get("format", "ascii")
    if fmt == "ascii":
        return [float(v) for v in text.split()]
    if fmt != "binary":
        raise RunError(f"VTU data format '{fmt}' is not supported")
    code = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
            "UInt8": "B", "UInt32": "I", "UInt64": "Q", "Int8": "b"}[dtype]
    word = 8 if header_type == "UInt64" else 4
    hcode = "Q" if word == 8 else "I"
    if not compressed:
        raw = base64.b64decode(text)
        size = struct.unpack("<" + hcode, raw[:word])[0]
        payload = raw[word:word + size]
    else:
        # The header (number of blocks, block size, last block size, the
        # compressed size of each block) is encoded on its own, then the
        # blocks.
        first = base64.b64decode(text[:4 * math.ceil(word / 3) + 4])
        n_blocks = struct.unpack("<" + hcode, first[:word])[0]
        header_bytes = (3 + n_blocks) * word
        header_chars = 4 * math.ceil(header_bytes / 3)
        header = struct.unpack("<%d%s" % (3 + n_blocks, hcode),
                               base64.b64decode(text[:header_chars])[:header_bytes])
        data = base64.b64decode(text[header_chars:])
        payload, offset = b"", 0
        for size in header[3:]:
            payload += zlib.decompress(data[offset:offset + size])
            offset += size
    count = len(payload) // struct.calcsize(code)
    return list(struct.unpack("<%d%s" % (count, code), payload))


def read_vtu(path):
    """Cells (lists of (x, y) corners) and the cell average of each point
    field of a VTU file."""
    root = ElementTree.parse(path).getroot()
    header_type = root.get("header_type", "UInt32")
    compressed = root.get("compressor") is not None
    cells, fields = [], {}
    for piece in root.iter("Piece"):
        def arrays(tag):
            block = piece.find(tag)
            return [] if block is None else block.findall("DataArray")

        points_array = arrays("Points")[0]
        coords = decode_data_array(points_array, points_array.get("type"),
                                   header_type, compressed)
        n_comp = int(points_array.get("NumberOfComponents", "3"))
        points = [(coords[i], coords[i + 1]) for i in range(0, len(coords), n_comp)]
        cell_arrays = {a.get("Name"): a for a in arrays("Cells")}
        conn = decode_data_array(cell_arrays["connectivity"],
                                 cell_arrays["connectivity"].get("type"),
                                 header_type, compressed)
        offsets = decode_data_array(cell_arrays["offsets"],
                                    cell_arrays["offsets"].get("type"),
                                    header_type, compressed)
        types = decode_data_array(cell_arrays["types"],
                                  cell_arrays["types"].get("type"),
                                  header_type, compressed)
        # Corners of the polygon of each cell: triangles (5, quadratic 22)
        # and quadrilaterals (9, quadratic 23 and 28).
        corners = {5: 3, 22: 3, 9: 4, 23: 4, 28: 4}
        point_data = {}
        for a in arrays("PointData"):
            if int(a.get("NumberOfComponents", "1")) == 1:
                point_data[a.get("Name")] = decode_data_array(
                    a, a.get("type"), header_type, compressed)
        start = 0
        for end, kind in zip(offsets, types):
            ids = conn[int(start):int(end)]
            start = end
            n = corners.get(int(kind))
            if n is None:
                continue
            cells.append([points[int(i)] for i in ids[:n]])
            for name, values in point_data.items():
                fields.setdefault(name, []).append(
                    sum(values[int(i)] for i in ids) / len(ids))
    return cells, fields


def last_vtu_meshes(run):
    """{body: (cells, fields)} of the last step's VTU files, or {}."""
    groups = sorted(glob.glob(run.path("bodies-*.pvtu")))
    if not groups:
        return {}
    root = ElementTree.parse(groups[-1]).getroot()
    meshes = {}
    for piece in root.iter("Piece"):
        source = piece.get("Source")
        body = re.sub(r"-\d{4}(\.\d+)?\.vtu$", "", source)
        cells, fields = read_vtu(run.path(source))
        old_cells, old_fields = meshes.get(body, ([], {}))
        old_cells += cells
        for name, values in fields.items():
            old_fields.setdefault(name, []).extend(values)
        meshes[body] = (old_cells, old_fields)
    return meshes


def last_csv_meshes(run):
    """{body: (cells, fields)} from the last cells_<body>-NNNN.csv."""
    by_body = {}
    for path in sorted(glob.glob(run.path("cells_*-[0-9][0-9][0-9][0-9].csv"))):
        body = re.sub(r"-\d{4}\.csv$", "", os.path.basename(path)[len("cells_"):])
        by_body[body] = path
    meshes = {}
    for body, path in by_body.items():
        data = read_csv(path)
        cells = [[(r[f"x{i}"], r[f"y{i}"]) for i in range(4)] for r in data]
        meshes[body] = (cells, {"von_mises": [r["von_mises"] for r in data]})
    return meshes


# --------------------------------------------------------------------------
# The abscissa of the profiles along S_1


def order_along_zone(xy):
    """The order of the points xy (an n x 2 array) along the curve they lie
    on, and whether that curve is closed: a chain grown from the first
    point at both ends, each time by the unvisited point nearest to either
    end. Neighbours along a curve are nearer than points across it unless
    the curve comes back within one point spacing of itself."""
    import numpy as np
    n = len(xy)
    free = np.ones(n, dtype=bool)
    free[0] = False
    chain = [0]
    for _ in range(n - 1):
        d_head = np.where(free, np.hypot(*(xy - xy[chain[0]]).T), np.inf)
        d_tail = np.where(free, np.hypot(*(xy - xy[chain[-1]]).T), np.inf)
        i, j = int(np.argmin(d_head)), int(np.argmin(d_tail))
        if d_head[i] < d_tail[j]:
            chain.insert(0, i)
        else:
            chain.append(j)
            i = j
        free[i] = False
    steps = np.hypot(*np.diff(xy[chain], axis=0).T)
    gap = float(np.hypot(*(xy[chain[-1]] - xy[chain[0]])))
    closed = n > 3 and gap <= 2 * float(steps.max())
    return chain, closed


def zone_abscissa(points, reference=None):
    """Sets p["s"], the position along S_1 that the profiles are drawn
    against, on every point, and returns the axis label.

    A straight zone keeps x1 (x2 if it is closer to vertical). On a curved
    one, x1 may run back and forth (a pin in a hole: the two halves of the
    circle would interleave into a comb), so s is the arc length along the
    polyline of the points (order_along_zone), counted from the point of
    largest pressure (or the point nearest @p reference, an (x1, x2)) where
    s equals that point's x1 (x2 on a vertical tangent), growing as x1 does
    there; a closed curve is cut opposite that point. Near a contact whose
    tangent is horizontal s is then close to x1, so the Hertz fit in s is
    the fit in x1. Returns (label, the reference point)."""
    import numpy as np
    xy = np.array([[p["x1"], p["x2"]] for p in points], dtype=float)
    centre = xy.mean(axis=0)
    _, _, axes = np.linalg.svd(xy - centre, full_matrices=False)
    along = (xy - centre) @ axes[0]
    across = (xy - centre) @ axes[1] if len(axes) > 1 else along * 0
    extent = float(along.max() - along.min()) if len(points) else 0.
    if len(points) < 3 or float(abs(across).max()) <= 1e-9 * max(extent, 1e-300):
        key = "x1" if abs(axes[0][0]) >= abs(axes[0][1]) else "x2"
        for p in points:
            p["s"] = p[key]
        return f"$x_{key[1]}$ along $S_1$", None
    chain, closed = order_along_zone(xy)
    ordered = xy[chain]
    lengths = np.concatenate([[0.], np.cumsum(np.hypot(*np.diff(ordered, axis=0).T))])
    if reference is None:
        ref = int(np.argmax([points[i]["pressure"] for i in chain]))
    else:
        ref = int(np.argmin(np.hypot(*(ordered - np.asarray(reference)).T)))
    s = lengths - lengths[ref]
    if closed:
        total = lengths[-1] + float(np.hypot(*(ordered[-1] - ordered[0])))
        s = (s + total / 2) % total - total / 2
    tangent = ordered[min(ref + 1, len(chain) - 1)] - ordered[max(ref - 1, 0)]
    key = 0 if abs(tangent[0]) >= abs(tangent[1]) else 1
    if tangent[key] < 0:
        s = -s
    s = s + ordered[ref][key]
    for i, value in zip(chain, s):
        points[i]["s"] = float(value)
    return (f"arc length $s$ along $S_1$ ({'closed' if closed else 'curved'}; "
            f"$s = x_{key + 1}$ at ({ordered[ref][0]:.3g}, "
            f"{ordered[ref][1]:.3g}))", tuple(ordered[ref]))


# --------------------------------------------------------------------------
# Hertz


def fit_parabola(xs, ys):
    """Least-squares y = A x^2 + B x + C; returns (A, B, C, rms residual)."""
    n = len(xs)
    s = [sum(x ** k for x in xs) for k in range(5)]
    t = [sum(y * x ** k for x, y in zip(xs, ys)) for k in range(3)]
    m = [[s[4], s[3], s[2], t[2]], [s[3], s[2], s[1], t[1]],
         [s[2], s[1], s[0], t[0]]]
    for i in range(3):  # Gauss-Jordan with partial pivoting
        p = max(range(i, 3), key=lambda r: abs(m[r][i]))
        m[i], m[p] = m[p], m[i]
        if m[i][i] == 0:
            return None
        for r in range(3):
            if r != i:
                f = m[r][i] / m[i][i]
                m[r] = [a - f * b for a, b in zip(m[r], m[i])]
    a, b, c = (m[i][3] / m[i][i] for i in range(3))
    rms = math.sqrt(sum((a * x * x + b * x + c - y) ** 2
                        for x, y in zip(xs, ys)) / n)
    return a, b, c, rms


def centre_of_pressure(points):
    force = sum(p["pressure"] * p["weight"] for p in points)
    return sum(p["s"] * p["pressure"] * p["weight"] for p in points) / force


def symmetry_of(run, bodies, points, x0, option):
    """Whether a pair is a half model (the rule of the module docstring):
    (True, why), (False, why), or (None, why) when the rule cannot tell."""
    if option != "auto":
        return option == "half", f"--symmetry {option}"
    active = [p["s"] for p in points if p["pressure"] > 0]
    tol = 0.1 * (max(active) - min(active))
    ends = [p for p in (points[0], points[-1])
            if abs(p["s"] - x0) <= tol and p["pressure"] > 0]
    rollers = []
    for body in bodies:
        for bid, where in run.rollers(body):
            if where is None or (where is not False and abs(where - x0) <= tol):
                rollers.append(f"{body} id {bid}")
    if not ends:
        return False, "the contact zone spans the parabola's vertex"
    if not rollers:
        return None, (f"the contact zone S_1 ends at the parabola's vertex "
                      f"x1 = {x0:.4g}, but no body of the pair has a roller "
                      "u_1 = 0 there: give --symmetry half or full")
    return True, (f"S_1 ends at the vertex x1 = {x0:.4g}, rollers u_1 = 0 "
                  f"on {', '.join(rollers)}")


CYLINDER = "a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), P per unit thickness"
SPHERE = "a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2), P the ring's total"


def pair_materials(run, pair):
    """The names of the pair's bodies and their [(E, nu)], or None for the
    materials where parameters.prm lacks one."""
    bodies = [b for b in (run.parameters.get(f"Contact pair {pair}/Body {i}")
                          for i in (1, 2)) if b]
    materials = [run.material(b) for b in bodies]
    if len(materials) != 2 or None in materials:
        return bodies, None
    return bodies, materials


def hertz_reference(run, pair, points, mode, symmetry="auto"):
    """The Hertz curve for a pair (points sorted by x1), or (None, why
    not): the cylinder's in plane strain, the sphere's in axisymmetry."""
    if mode == "off":
        return None, "off"
    active = [p for p in points if p["pressure"] > 0]
    if len(active) < 5:
        return None, "fewer than 5 points in contact"
    if run.axisymmetric:
        return hertz_sphere(run, pair, points, active, mode, symmetry)
    force = sum(p["pressure"] * p["weight"] for p in points)
    centre = centre_of_pressure(points)
    half = max(abs(p["s"] - centre) for p in active)
    window = [p for p in points if abs(p["s"] - centre) <= 2 * half]
    fit = fit_parabola([p["s"] for p in window], [p["gap"] for p in window])
    if fit is None:
        return None, "gap not parabolic"
    a2, b1, _, rms = fit
    rise = a2 * (2 * half) ** 2
    scale = max(abs(p["gap"]) for p in points) + max(
        abs(p["u_1n"] + p["u_2n"]) for p in points)
    if a2 <= 0 or rise <= 1e-6 * scale or rms > 0.02 * rise:
        return None, "the initial gap is not a parabola about the contact"
    radius, x0 = 1 / (2 * a2), -b1 / (2 * a2)
    bodies, materials = pair_materials(run, pair)
    if materials is None:
        return None, "materials of the pair not found in parameters.prm"
    half_model, model_why = symmetry_of(run, bodies, points, x0, symmetry)
    if half_model is None:
        return None, model_why
    whole = 2 * force if half_model else force
    e_star = 1 / sum((1 - nu * nu) / e for e, nu in materials)
    a = math.sqrt(4 * whole * radius / (math.pi * e_star))
    p0 = 2 * whole / (math.pi * a)
    zone = max(p["s"] for p in points) - min(p["s"] for p in points)
    if half_model:
        zone *= 2
    heights = [h for h in (run.rectangle_height(b) for b in bodies) if h]
    limit = min([zone] + heights)
    info = dict(pair=pair, geometry="plane strain", closed_form="cylinder",
                formula=CYLINDER, model="half" if half_model else "full",
                model_reason=model_why, zone_force=force, whole_force=whole,
                R=radius, x0=x0, E_star=e_star, a=a, p0=p0,
                a_over_L=a / limit)
    model = f"{info['model']} model: {model_why}"
    if mode == "auto" and a > 0.1 * limit:
        return None, (f"half-width a = {a:.3g} is {a / limit:.2g} of the zone "
                      f"or body size (half-plane needs <= 0.1); {model}")
    return info, f"R = {radius:.4g}, a/L = {a / limit:.2g}; {model}"


def hertz_sphere(run, pair, points, active, mode, symmetry):
    """Hertz's sphere on an axisymmetric run (x1 = r): the gap
    f0 + r^2/(2R) fitted over the contact disc, the contact reaching the
    axis, and the closed form at the ring's force, which is the whole force
    (no half models: r = 0 is the axis, not a cut)."""
    force = sum(p["pressure"] * p["weight"] for p in points)
    reach = max(p["x1"] for p in active)
    if min(p["x1"] for p in active) > 0.1 * reach:
        return None, (f"axisymmetric: the contact lies at "
                      f"{min(p['x1'] for p in active):.4g} <= r <= {reach:.4g}, "
                      "away from the axis: not a sphere's disc")
    # Hertz needs the profile inside the contact only. Past it the cells
    # coarsen, and the gap (the expression interpolated on each face) lies
    # above the parabola by up to h^2/(8R): over twice the radius R came out
    # 0.4 % short on prm/hertz_sphere.prm at box refinement 6, over the
    # disc 4e-7.
    window = [p for p in points if p["x1"] <= reach]
    # Least squares in u = r^2: f = A u + C.
    u = [p["x1"] ** 2 for p in window]
    f = [p["gap"] for p in window]
    n, su, sf = len(u), sum(u), sum(f)
    suu = sum(v * v for v in u)
    det = n * suu - su * su
    if det <= 1e-12 * n * suu:
        return None, "axisymmetric: the zone is not across the axis (no sphere)"
    a2 = (n * sum(v * g for v, g in zip(u, f)) - su * sf) / det
    c0 = (sf - a2 * su) / n
    rms = math.sqrt(sum((a2 * v + c0 - g) ** 2 for v, g in zip(u, f)) / n)
    rise = a2 * reach ** 2
    scale = max(abs(p["gap"]) for p in points) + max(
        abs(p["u_1n"] + p["u_2n"]) for p in points)
    if a2 <= 0 or rise <= 1e-6 * scale or rms > 0.02 * rise:
        return None, ("axisymmetric: the initial gap is not f0 + r^2/(2R) "
                      "about the axis (no sphere)")
    radius = 1 / (2 * a2)
    bodies, materials = pair_materials(run, pair)
    if materials is None:
        return None, "materials of the pair not found in parameters.prm"
    e_star = 1 / sum((1 - nu * nu) / e for e, nu in materials)
    a = (3 * force * radius / (4 * e_star)) ** (1 / 3)
    p0 = 3 * force / (2 * math.pi * a * a)
    # Half-space: a against the zone's radial extent (the body's radius
    # for a zone up to its rim) and the bodies' heights.
    zone = max(p["x1"] for p in points) - min(p["x1"] for p in points)
    heights = [h for h in (run.rectangle_height(b) for b in bodies) if h]
    limit = min([zone] + heights)
    why = "Geometry = axisymmetric: the sphere's force is the ring's total"
    if symmetry != "auto":
        why += f" (--symmetry {symmetry} ignored: no half models in axisymmetry)"
    info = dict(pair=pair, geometry="axisymmetric", closed_form="sphere",
                formula=SPHERE, model="axisymmetric", model_reason=why,
                zone_force=force, whole_force=force, R=radius, x0=0.,
                E_star=e_star, a=a, p0=p0, a_over_L=a / limit)
    if mode == "auto" and a > 0.1 * limit:
        return None, (f"sphere: contact radius a = {a:.3g} is {a / limit:.2g} "
                      f"of the zone or body size (half-space needs <= 0.1); {why}")
    return info, f"sphere, R = {radius:.4g}, a/L = {a / limit:.2g}; {why}"


# --------------------------------------------------------------------------
# Cattaneo-Mindlin and Mindlin-Deresiewicz


def dundurs_beta(materials):
    """Dundurs' beta of two bodies [(E, nu), (E, nu)] in plane strain: 0
    for elastically similar bodies, whose shear leaves the pressure alone."""
    (e1, nu1), (e2, nu2) = materials
    g1, g2 = e1 / (2 * (1 + nu1)), e2 / (2 * (1 + nu2))
    k1, k2 = 3 - 4 * nu1, 3 - 4 * nu2
    return (g1 * (k2 - 1) - g2 * (k1 - 1)) / (g1 * (k2 + 1) + g2 * (k1 + 1))


def step_list(steps):
    """Load step numbers as text, runs joined: [1, 2, 3, 5] -> "1-3, 5"."""
    runs = []
    for k in steps:
        if runs and k == runs[-1][1] + 1:
            runs[-1][1] = k
        else:
            runs.append([k, k])
    return ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs)


# How far from press-then-shear a load path may be and still be drawn with
# the closed forms, as a fraction of mu P (a tangential force) and of P (a
# normal force). The closed forms depend on Q only through Q/(mu P) (c = a
# sqrt(1 - |Q|/(mu P))) and on P through a ~ P^(1/2): a shear of eps mu P
# already on in the press step, or a drift of eps P of the normal force
# under the shear, moves t by about eps mu p0 and the stick edge c by about
# eps a (at c/a = 1/2). At 1 % that is below what the curve is compared
# with: the computed t is 2.7-14 % of the norm of mu p off the closed form
# in L2 on the meshes of doc/friction.md section 5.2, its stick edge known
# to a cell, h >= a/36 there. A press step that carries a tangential force
# of 0.03 % of P (0.1 % of mu P at mu = 0.3) is then still press-then-shear;
# a tolerance relative to the largest Q took it for a shear under a changing
# P. Pressing and shearing together stays refused: P grows by its whole
# value while Q is on.
PATH_TOLERANCE = 0.01


def tangential_path(history, mu=None, tolerance=PATH_TOLERANCE):
    """How the load steps [(P_k, Q_k)] (normal and tangential force after
    each step) reached the last one, for the closed forms of a shear at a
    constant normal force: ("monotone", None, why), ("reversal", Q*, why)
    with Q* the tangential force where it turned, or (None, None, why).

    A load step solves the tangential problem on the contact of its end, so
    a step that presses and shears at once is a shear at its final normal
    force: Cattaneo-Mindlin's case as long as P stays the same from the
    first step that puts Q on. "The same" and "puts on" within @p tolerance
    of P and of mu P (of the largest |Q| without mu): see PATH_TOLERANCE.
    The shear turns where Q goes back from its running extreme by more
    than that, so that many small steps still count as one shear."""
    forces = [0.] + [q for _, q in history]
    normal = [0.] + [p for p, _ in history]
    P = abs(normal[-1])
    q_tol = tolerance * (mu * P if mu and P else max(abs(q) for q in forces))
    p_tol = tolerance * P
    on = [k for k in range(1, len(forces)) if abs(forces[k]) > q_tol]
    if not on:
        return None, None, "no tangential force"
    changed = [k for k in range(on[0], len(forces))
               if abs(normal[k] - normal[-1]) > p_tol]
    if changed:
        return None, None, (
            f"the normal force changes in load steps {step_list(changed)} of "
            f"{len(history)} while the tangential force is on (by more than "
            f"{tolerance:.0%} of P): the closed forms hold P constant under "
            "the shear (pressing and shearing together has none here)")
    # Hysteresis: the running extreme of Q since the last turn.
    turns, sign, peak, peak_k = [], 0, 0., 0
    for k in range(1, len(forces)):
        q = forces[k]
        if sign == 0:
            if abs(q) > q_tol:
                sign, peak, peak_k = math.copysign(1, q), q, k
        elif (q - peak) * sign >= 0:
            peak, peak_k = q, k
        elif abs(q - peak) > q_tol:
            turns.append(peak_k)
            sign, peak, peak_k = -sign, q, k
    note = (f" (within {tolerance:.0%} of mu P and of P)" if mu else "")
    if not turns:
        return "monotone", None, "Q grows monotonically at constant P" + note
    if len(turns) == 1:
        return "reversal", forces[turns[0]], (
            f"Q turns once, after load step {turns[0]}, at constant P" + note)
    return None, None, (
        f"the tangential force turns {len(turns)} times (after load steps "
        f"{step_list(turns)}): the closed form here covers one reversal "
        "(Mindlin-Deresiewicz)")


def cattaneo_traction(v, a, p0, mu, P, Q):
    """Cattaneo-Mindlin's traction at v from the centre of a Hertz contact
    (a, p0) under the normal force P and the tangential force Q (the
    integral of t, signed), |Q| <= mu P:
    t = sign(Q) mu p0/a (sqrt(a^2 - v^2) - sqrt(c^2 - v^2)), each root 0
    outside its zone, c = a sqrt(1 - |Q|/(mu P))."""
    c = a * math.sqrt(max(0., 1 - abs(Q) / (mu * P)))
    return math.copysign(1, Q) * mu * p0 / a * (
        math.sqrt(max(0., a * a - v * v)) - math.sqrt(max(0., c * c - v * v)))


# --------------------------------------------------------------------------
# Figures


def zoom_window(points):
    """Where to draw a contact profile: the whole zone, or three times the
    contact area around it when that is less than a third of the zone.
    Returns (the test of a position, whether it zooms)."""
    active = [p["s"] for p in points if p["pressure"] > 0]
    lo, hi = min(p["s"] for p in points), max(p["s"] for p in points)
    if not active:
        return (lambda x: True), False
    centre, half = (min(active) + max(active)) / 2, (max(active) - min(active)) / 2
    if 2 * half >= (hi - lo) / 3 or half == 0:
        return (lambda x: True), False
    left, right = max(lo, centre - 3 * half), min(hi, centre + 3 * half)
    return (lambda x: left <= x <= right), True


class Plotter:
    def __init__(self, run, out, units, hertz, dpi, symmetry="auto"):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        self.plt = plt
        self.run, self.out, self.hertz, self.dpi = run, out, hertz, dpi
        self.symmetry = symmetry
        length, stress = units
        self.length = f"[{length}]"
        self.stress = f"[{stress}]"
        # A force is a stress times a length per unit thickness in plane
        # strain, the total over the ring (2 pi r) in axisymmetry.
        self.axisymmetric = run.axisymmetric
        square = "^2" if self.axisymmetric else ""
        self.force = (f"[{stress} {length}{square}]" if units != ("length", "stress")
                      else f"[stress x length{square}]")
        self.force_kind = ("total over the ring" if self.axisymmetric
                           else "per unit thickness")
        self.written = []

    def save(self, fig, name):
        path = os.path.join(self.out, name)
        fig.tight_layout()
        fig.savefig(path, dpi=self.dpi)
        self.plt.close(fig)
        self.written.append(path)

    def contact(self):
        for pair in self.run.pair_names():
            path = self.run.path(f"contact_{pair}.csv")
            if not os.path.isfile(path):
                continue
            points = read_csv(path)
            if not points:
                continue
            axis, reference = zone_abscissa(points)
            if self.axisymmetric and reference is None:
                axis = axis.replace("$x_1$", "radius $r = x_1$").replace(
                    "$x_2$", "axis $z = x_2$")
            points.sort(key=lambda p: p["s"])
            force = sum(p["pressure"] * p["weight"] for p in points)
            peak = max(p["pressure"] for p in points)
            info, why = hertz_reference(self.run, pair, points, self.hertz,
                                        self.symmetry)
            print(f"{PROGRAM}: pair {pair}: Hertz curve "
                  f"{'drawn' if info else 'not drawn'} ({why})")
            self.hertz_record(pair, info)
            inside, zoom = zoom_window(points)
            friction = "tangential_traction" in points[0]
            if friction:
                fig, (ax, bx, cx) = self.plt.subplots(3, 1, figsize=(8, 9.2),
                                                      sharex=True)
            else:
                fig, (ax, bx) = self.plt.subplots(2, 1, figsize=(8, 6.4),
                                                  sharex=True)
            shown = [p for p in points if inside(p["s"])]
            x = [p["s"] for p in shown]
            iterates = sorted(glob.glob(self.run.path(f"contact_{pair}_[0-9][0-9][0-9][0-9].csv")))
            for i, it in enumerate(iterates):
                q = read_csv(it)
                if not q:
                    continue
                zone_abscissa(q, reference)
                q = sorted((p for p in q if inside(p["s"])), key=lambda p: p["s"])
                ax.plot([p["s"] for p in q], [p["pressure"] for p in q],
                        color="0.75", linewidth=0.7,
                        label=f"iterates ({len(iterates)} files)" if i == 0 else None)
            ax.plot(x, [p["pressure"] for p in shown], "o-", markersize=2.5,
                    linewidth=1.2, color="tab:blue", label="computed")
            if info:
                # A half model's curve only on its side of the vertex, the
                # sphere's from the axis.
                left = info["x0"] - info["a"]
                right = info["x0"] + info["a"]
                if info["closed_form"] == "sphere":
                    left = 0.
                elif info["model"] == "half":
                    if centre_of_pressure(points) >= info["x0"]:
                        left = info["x0"]
                    else:
                        right = info["x0"]
                xs = [left + (right - left) * i / 400 for i in range(401)]
                label = (f"Hertz, half model: whole force 2P = "
                         f"{info['whole_force']:.4g}" if info["model"] == "half"
                         else "Hertz sphere at the computed ring force"
                         if info["closed_form"] == "sphere"
                         else "Hertz at the computed force")
                ax.plot(xs, [info["p0"] * math.sqrt(max(0., 1 - ((v - info["x0"]) / info["a"]) ** 2))
                             for v in xs], "k--", linewidth=1.2,
                        label=f"{label}: a = {info['a']:.4g}, "
                              f"p0 = {info['p0']:.4g}")
            ax.set_ylabel(f"contact pressure $-\\sigma_n$ {self.stress}")
            half_note = ""
            if info and info["model"] == "half":
                half_note = (f"\nhalf model: whole force 2P = "
                             f"{info['whole_force']:.5g} {self.force} "
                             f"(symmetry line $x_1$ = {info['x0']:.3g})")
            kind = ("ring force (total over 2$\\pi r$)" if self.axisymmetric
                    else "force per unit thickness")
            ax.set_title(f"contact pair {pair}"
                         + (" (zoomed to the contact area)" if zoom else "")
                         + f"\n{kind} {force:.5g} {self.force}, "
                         f"peak pressure {peak:.5g} {self.stress}" + half_note,
                         fontsize=9)
            # Headroom for the legend above the profile.
            ax.set_ylim(top=1.4 * max([peak] + ([info["p0"]] if info else [])))
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=8, loc="upper right")
            current = [p["gap"] - p["u_1n"] - p["u_2n"] for p in shown]
            bx.plot(x, current, "-", color="tab:red",
                    label="gap after deformation $f_n - u_{1n} - u_{2n}$ "
                          f"(smallest {min(current):.3g})")
            bx.axhline(0, color="k", linewidth=0.8)
            if not friction:
                bx.set_xlabel(f"{axis} {self.length}")
            bx.set_ylabel(f"gap {self.length} (< 0: penetration)")
            bx.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
            bx.grid(True, alpha=0.3)
            bx.legend(fontsize=8, loc="upper center")
            if friction:
                self.friction(pair, points, shown, info, cx, axis)
            self.save(fig, f"contact_{pair}.png")

    def friction(self, pair, points, shown, info, cx, axis):
        """The tangential traction along the zone, its Coulomb bound and,
        on a Hertz contact, Cattaneo-Mindlin's closed form."""
        x = [p["s"] for p in shown]
        t = [p["tangential_traction"] for p in shown]
        law = self.run.parameters.get(f"Contact pair {pair}/Friction", "")
        mu = self.run.constant(self.run.parameters.get(
            f"Contact pair {pair}/Friction coefficient"))
        Q = sum(p["tangential_traction"] * p["weight"] for p in points)
        P = sum(p["pressure"] * p["weight"] for p in points)
        # In axisymmetry t is radial and its ring integral is a sum of ring
        # forces without a 3D resultant: no Q to speak of.
        cx.plot(x, t, "o-", markersize=2.5, linewidth=1.2, color="tab:green",
                label=("computed radial traction t" if self.axisymmetric else
                       f"computed t (Q = {Q:.4g} {self.force})"))
        sign = 1 if Q >= 0 else -1
        if law == "coulomb" and mu is not None:
            cx.plot(x, [sign * mu * p["pressure"] for p in shown], ":",
                    color="0.4", label=f"slip bound $\\pm\\mu p$, $\\mu$ = {mu:.3g}")
            # The other side of the bound where t reaches toward it (slip
            # reversed after unloading, or a curved zone).
            if self.axisymmetric or any(sign * v < -0.05 * max(map(abs, t))
                                        for v in t):
                cx.plot(x, [-sign * mu * p["pressure"] for p in shown], ":",
                        color="0.4")
        record = os.path.join(self.out, f"mindlin_{pair}.json")
        used = None
        if self.axisymmetric:
            if law == "coulomb":
                print(f"{PROGRAM}: pair {pair}: no Cattaneo-Mindlin curve "
                      "(axisymmetric: the traction is radial, without a "
                      "tangential force; a sheared sphere is not a body of "
                      "revolution's problem)")
        elif law == "coulomb" and mu and info and Q != 0:
            used, why = self.mindlin(pair, mu, P, Q, info)
            if used is None:
                print(f"{PROGRAM}: pair {pair}: no Cattaneo-Mindlin curve ({why})")
        if used:
            a, x0 = info["a"], info["x0"]
            xs = [x0 - a + 2 * a * i / 400 for i in range(401)]
            cx.plot(xs, [used["traction"](v - x0) for v in xs], "k--",
                    linewidth=1.2, label=used["label"])
            print(used["line"])
            with open(record, "w") as f:
                json.dump(used["record"], f, indent=2)
                f.write("\n")
            self.written.append(record)
        elif os.path.isfile(record):
            os.remove(record)
        cx.axhline(0, color="k", linewidth=0.8)
        cx.set_xlabel(f"{axis} {self.length}")
        cx.set_ylabel(f"tangential traction t {self.stress}")
        cx.grid(True, alpha=0.3)
        cx.legend(fontsize=8, loc="upper right")

    def load_history(self, pair):
        """[(P_k, Q_k)] after each load step: the integrals of the pressure
        and of t over contact_<pair>_stepNNNN.csv (the plotted t's sign),
        else summary.json's load_steps (normal_force, and -tangential_force,
        the force on body 1); [] when the run has neither."""
        steps = sorted(glob.glob(self.run.path(f"contact_{pair}_step[0-9][0-9][0-9][0-9].csv")))
        history = []
        for path in steps:
            rows = read_csv(path)
            history.append((sum(p["pressure"] * p["weight"] for p in rows),
                            sum(p.get("tangential_traction", 0.) * p["weight"]
                                for p in rows)))
        if history:
            return history
        for step in self.run.summary.get("load_steps") or []:
            for entry in step.get("pairs", []):
                if entry.get("pair") == pair:
                    if "normal_force" not in entry or "tangential_force" not in entry:
                        return []
                    history.append((entry["normal_force"], -entry["tangential_force"]))
        return history

    def mindlin(self, pair, mu, P, Q, info):
        """The closed form of the tangential traction for the run's load
        path at the Hertz contact info, as a dict (traction of the offset
        from the centre, legend label, console line, record), or (None, why
        not). Monotone shear at constant P: Cattaneo-Mindlin at Q. One
        reversal from Q* back to Q (Mindlin-Deresiewicz, in 2D the same
        superposition as in 3D): t = t_CM(Q*) - 2 t_CM((Q* - Q)/2), which
        slips backwards for c' < |x - x0| < a, c' = a sqrt(1 - |Q* - Q|/(2 mu
        P)), keeps the loading's traction and slip inside c* = a sqrt(1 -
        |Q*|/(mu P)) plus the reversal's locked-in part between c* and c',
        and meets Q; once Q has gone past -Q*, the first loading is
        forgotten and Cattaneo-Mindlin at Q holds again (doc/friction.md
        section 5.2)."""
        _, materials = pair_materials(self.run, pair)
        if materials is None:
            return None, "materials of the pair not found in parameters.prm"
        beta = dundurs_beta(materials)
        if abs(beta) > 1e-6:
            return None, (f"the bodies are not elastically similar (Dundurs' "
                          f"beta = {beta:.3g}): the shear changes the pressure")
        history = self.load_history(pair) or [(P, Q)]
        if history[-1][1] * Q < 0:
            history = [(p, -q) for p, q in history]
        history[-1] = (P, Q)
        kind, Q_star, why = tangential_path(history, mu)
        if kind is None:
            return None, why
        slack = 1 + 1e-6
        a, p0 = info["a"], info["p0"]
        record = {"pair": pair, "mu": mu, "Q": Q, "P": P, "a": a, "path": kind}
        if kind == "reversal" and Q * math.copysign(1, Q_star) < -abs(Q_star):
            kind, why = "monotone", (f"Q went past -Q* = {-Q_star:.4g}: the "
                                     "first loading is forgotten")
            record["path"] = "reversal beyond -Q*"
        if kind == "monotone":
            if abs(Q) > mu * P * slack:
                return None, f"|Q| = {abs(Q):.4g} above mu P = {mu * P:.4g}"
            c = a * math.sqrt(max(0., 1 - abs(Q) / (mu * P)))
            record.update(c=c, c_over_a=c / a)
            return dict(
                traction=lambda v: cattaneo_traction(v, a, p0, mu, P, Q),
                label=f"Cattaneo-Mindlin: c = {c:.4g}, c/a = {c / a:.4g}",
                line=(f"mindlin {pair}: c = {c:.6g}, c/a = {c / a:.6g} "
                      f"(Q/(mu P) = {abs(Q) / (mu * P):.6g}, a = {a:.6g}; {why})"),
                record=record), why
        if abs(Q_star) > mu * P * slack:
            return None, f"|Q*| = {abs(Q_star):.4g} above mu P = {mu * P:.4g}"
        c_star = a * math.sqrt(max(0., 1 - abs(Q_star) / (mu * P)))
        c = a * math.sqrt(max(0., 1 - abs(Q_star - Q) / (2 * mu * P)))
        record.update(Q_star=Q_star, c_star=c_star, c=c, c_over_a=c / a)
        return dict(
            traction=lambda v: (cattaneo_traction(v, a, p0, mu, P, Q_star) -
                                2 * cattaneo_traction(v, a, p0, mu, P,
                                                      (Q_star - Q) / 2)),
            label=(f"Mindlin-Deresiewicz, from Q* = {Q_star:.4g}: "
                   f"c' = {c:.4g}, c'/a = {c / a:.4g}"),
            line=(f"mindlin {pair}: unloaded from Q* = {Q_star:.6g} to Q = "
                  f"{Q:.6g} (Mindlin-Deresiewicz): c' = {c:.6g}, c'/a = "
                  f"{c / a:.6g}, slip reversed for c' < |x - x0| < a; c* = "
                  f"{c_star:.6g} of the loading (a = {a:.6g}; {why})"),
            record=record), why

    def hertz_record(self, pair, info):
        """Print the closed form used for a pair and write it to
        hertz_<pair>.json; remove a stale file when there is none."""
        path = os.path.join(self.out, f"hertz_{pair}.json")
        if not info:
            if os.path.isfile(path):
                os.remove(path)
            return
        model = ("sphere, axisymmetric" if info["closed_form"] == "sphere"
                 else f"{info['model']} model")
        print(f"hertz {pair}: a = {info['a']:.6g}, p0 = {info['p0']:.6g}, "
              f"whole force {info['whole_force']:.6g} ({model}, "
              f"R = {info['R']:.6g}, E* = {info['E_star']:.6g})")
        with open(path, "w") as f:
            json.dump(info, f, indent=2)
            f.write("\n")
        self.written.append(path)

    # What history.csv's rows are for each contact solver: the title, the
    # abscissa, the residual's and the increment's meaning (doc/output.md,
    # doc/contact-solvers.md).
    SOLVERS = {
        "dd": ("Neumann domain decomposition (dd)", "DD iteration k",
               "residual $||\\tilde u^{k+1} - u^k|| / ||\\tilde u^{k+1}||$",
               "increment $||u^{k+1} - u^k|| / ||u^{k+1}||$"),
        "dd-newton": ("dd-newton: semismooth Newton on the contact "
                      "pressure", "Newton step k",
                      "Newton residual $||\\Phi(p)||_W$, relative",
                      "step of the pressure $\\tau ||x - p|| / ||p||$"),
        "monolithic": ("monolithic: semismooth Newton on all bodies at once",
                       "Newton solve k (one row per solve)",
                       "final Newton residual / that of the zero iterate",
                       None),
    }

    def convergence(self):
        rows = self.run.rows("history.csv")
        if not rows:
            return
        solver = self.run.solver
        name, abscissa, residual, increment = self.SOLVERS.get(
            solver, (f"contact solver {solver or '(not recorded)'}",
                     "iteration k", "residual", "increment"))
        k = [r["k"] for r in rows]
        fig, axes = self.plt.subplots(1, 3, figsize=(13, 3.9))
        positive = lambda values: [v if v > 0 else float("nan") for v in values]
        axes[0].semilogy(k, positive([r["residual"] for r in rows]),
                         label=residual)
        # The monolithic solver records no increment (zeros).
        if increment and any(r["increment"] for r in rows):
            axes[0].semilogy(k, positive([r["increment"] for r in rows]), "--",
                             label=increment)
        eps = number(self.run.parameters.get("Contact solver/Tolerance"))
        if eps:
            axes[0].axhline(eps, color="k", linewidth=0.8, linestyle=":",
                            label=f"Tolerance = {eps:g}")
        axes[0].set_ylabel("relative residual (dimensionless)")
        axes[0].legend(fontsize=7)
        summary = self.run.summary
        title = f"status: {summary.get('status', '?')}"
        if summary.get("uzawa_updates"):
            title += f", {summary['uzawa_updates']} augmented-Lagrangian updates"
        if summary.get("load_steps"):
            title += f", {len(summary['load_steps'])} load steps"
        axes[0].set_title(title, fontsize=9)
        # normal_force since issue 48 (contact_force, the norm of the force
        # vector, in older runs).
        column = "normal_force" if "normal_force" in rows[0] else "contact_force"
        axes[1].plot(k, [r[column] for r in rows], color="tab:green")
        axes[1].set_ylabel(f"normal force, all pairs, {self.force_kind}\n"
                           f"{self.force}")
        axes[2].semilogy(k, positive([r["max_penetration"] for r in rows]),
                         color="tab:red")
        axes[2].set_ylabel(f"largest penetration $u_{{1n}} + u_{{2n}} - f_n$ {self.length}")
        for ax in axes:
            ax.set_xlabel(abscissa)
            ax.grid(True, alpha=0.3)
        fig.suptitle(f"{name} (history.csv)")
        self.save(fig, "convergence.png")

    def force_displacement(self):
        """Each driven Dirichlet id's reaction against its mean
        displacement, per component (force_displacement.csv); where no id
        moves (loads by tractions), the reactions against t."""
        rows = self.run.rows("force_displacement.csv")
        if not rows:
            return
        supports = {}
        for r in rows:
            supports.setdefault((r["body"], int(r["boundary_id"])), []).append(r)
        # x is the radius in axisymmetry, where a radial reaction is a sum
        # of ring forces with no 3D resultant.
        names = ({"x": "radial (r)", "y": "axial (z)"} if self.axisymmetric
                 else {"x": "$x_1$", "y": "$x_2$"})
        driven = [(c, key) for c in ("y", "x") for key, rs in supports.items()
                  if any(r[f"u_{c}"] != 0 for r in rs)]
        components = [c for c in ("y", "x") if any(d[0] == c for d in driven)]
        against_t = not components
        if against_t:
            components = [c for c in ("y", "x")
                          if any(r[f"force_{c}"] != 0 for r in rows)] or ["y"]
        fig, axes = self.plt.subplots(1, len(components),
                                      figsize=(5.2 * len(components) + 1, 4.2),
                                      squeeze=False)
        for ax, c in zip(axes[0], components):
            for key, rs in supports.items():
                if not against_t and (c, key) not in driven:
                    continue
                xs = [r["t"] if against_t else r[f"u_{c}"] for r in rs]
                ax.plot(xs, [r[f"force_{c}"] for r in rs], "o-", markersize=3,
                        label=f"{key[0]}, Dirichlet id {key[1]}")
            ax.axhline(0, color="k", linewidth=0.8)
            ax.set_xlabel("load parameter t" if against_t else
                          f"mean displacement {names[c]} of the id {self.length}")
            ax.set_ylabel(f"reaction, {names[c]} component, {self.force_kind}\n"
                          f"{self.force}")
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=8)
        fig.suptitle("force-displacement (force_displacement.csv)"
                     + (", axisymmetric: ring forces" if self.axisymmetric
                        else ", plane strain: forces per unit thickness"),
                     fontsize=10)
        self.save(fig, "force_displacement.png")

    def load_path(self):
        """The steps the load path took (Loading/Steps = auto, or fixed
        steps with Check path): t after each accepted step, the step's
        length, and its estimated path error against Path tolerance."""
        path = self.run.summary.get("load_path")
        steps = self.run.summary.get("load_steps") or []
        if not isinstance(path, dict) or not steps:
            return
        errors = [s.get("path_error") for s in steps]
        auto = path.get("steps") == "auto"
        if not auto and all(e is None for e in errors):
            return
        number_ = [s["step"] for s in steps]
        t = [s["t"] for s in steps]
        start = [0.] + t[:-1]
        length = [b - a for a, b in zip(start, t)]
        fig, axes = self.plt.subplots(1, 3, figsize=(14, 4))
        from matplotlib.ticker import MaxNLocator
        axes[0].plot(number_, t, "o-", markersize=3)
        axes[0].xaxis.set_major_locator(MaxNLocator(integer=True))
        axes[0].set_xlabel("accepted load step" if auto else "load step")
        axes[0].set_ylabel("load parameter t at the step's end")
        axes[0].set_ylim(0, 1.05)
        axes[1].step(start + [t[-1]], length + [length[-1]], where="post")
        axes[1].set_yscale("log", base=2)
        axes[1].set_xlabel("load parameter t")
        axes[1].set_ylabel("step length $\\Delta t$")
        smallest = number(self.run.parameters.get("Loading/Max splits"))
        if auto and smallest:
            axes[1].axhline(2 ** -smallest, color="k", linewidth=0.8,
                            linestyle=":",
                            label=f"smallest allowed, $2^{{-{smallest:g}}}$")
            axes[1].legend(fontsize=8)
        # A step without an estimate (null) is left out; a zero one sits
        # at the floor of the log scale.
        floor = 1e-17
        shown = [(a, b, max(e, floor)) for a, b, e in zip(start, t, errors)
                 if e is not None]
        for i, (a, b, e) in enumerate(shown):
            axes[2].plot([a, b], [e, e], "-", color="tab:blue", linewidth=2,
                         label="estimate of the step" if i == 0 else None)
        tol = path.get("path_tolerance")
        if tol:
            axes[2].axhline(tol, color="tab:red", linewidth=1,
                            label=f"Path tolerance = {tol:g} "
                                  + ("(split above)" if auto else "(warned above)"))
            if auto:
                axes[2].axhline(tol / 4, color="tab:red", linewidth=0.8,
                                linestyle=":",
                                label="tolerance / 4 (the next step may double)")
        for i, (a, b) in enumerate(path.get("over_tolerance") or []):
            axes[2].axvspan(a, b, color="tab:red", alpha=0.15,
                            label="smallest step, still above" if i == 0 else None)
        axes[2].set_yscale("log")
        axes[2].set_xlabel("load parameter t")
        axes[2].set_ylabel("estimated path error of the step")
        axes[2].legend(fontsize=7)
        for ax in axes:
            ax.grid(True, alpha=0.3)
        total = path.get("path_error")
        title = (f"load path, Steps = {path.get('steps')}: {len(steps)} "
                 + ("accepted steps" if auto else "steps, Check path"))
        if auto:
            title += (f", {path.get('rejected_steps', '?')} splits, "
                      f"{path.get('solves', '?')} solves")
        if total is not None:
            title += f"; path error {total:.3g} (sum of the steps' estimates)"
        fig.suptitle(title + " (summary.json)", fontsize=10)
        print(f"{PROGRAM}: {title}")
        self.save(fig, "load_path.png")

    def adaptation(self):
        from matplotlib.ticker import MaxNLocator
        rows = self.run.rows("statistics.csv")
        if not rows:
            return
        cycle = [r["cycle"] for r in rows]
        bodies = [key[len("cells_"):] for key in rows[0] if key.startswith("cells_")]
        fig, axes = self.plt.subplots(1, 3, figsize=(13, 3.9))
        for body in bodies:
            axes[0].semilogy(cycle, [r["cells_" + body] for r in rows], "o-",
                             markersize=3, label=f"cells, {body}")
            axes[0].semilogy(cycle, [r["dofs_" + body] for r in rows], "s--",
                             markersize=3, label=f"dofs, {body}")
        if any(r["bem_unknowns"] for r in rows):
            axes[0].semilogy(cycle, [r["bem_unknowns"] for r in rows], "^:",
                             markersize=3, label="BEM unknowns")
        axes[0].set_ylabel("count")
        axes[0].set_title("mesh size", fontsize=9)
        axes[1].semilogy(cycle, [r["eta_max"] or float("nan") for r in rows],
                         "o-", markersize=3, label="largest indicator eta")
        if any(r["relative_error_estimate"] for r in rows):
            axes[1].semilogy(cycle, [r["relative_error_estimate"] or float("nan")
                                     for r in rows], "s--", markersize=3,
                             label="estimated relative stress error")
        delta = number(self.run.parameters.get("Adaptation/Delta"))
        marking = self.run.parameters.get("Adaptation/Marking", "threshold")
        if delta and marking == "threshold":
            axes[1].axhline(delta, color="k", linewidth=0.8, linestyle=":",
                            label=f"threshold delta = {delta:g}")
        axes[1].set_ylabel("indicator (dimensionless)")
        axes[1].set_title(f"estimator: "
                          f"{self.run.parameters.get('Adaptation/Estimator', '?')}",
                          fontsize=9)
        axes[2].plot(cycle, [r["marked"] for r in rows], "o-", markersize=3,
                     label="marked cells")
        axes[2].plot(cycle, [r["dd_iterations"] for r in rows], "s--",
                     markersize=3, label="DD iterations so far")
        axes[2].set_ylabel("count")
        for ax in axes:
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
            ax.set_xlabel("adaptation cycle")
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7)
        fig.suptitle("Adaptation (statistics.csv)")
        self.save(fig, "adaptation.png")

    def mesh(self):
        from matplotlib.collections import PolyCollection
        meshes, source = last_vtu_meshes(self.run), "VTU"
        if not meshes:
            meshes, source = last_csv_meshes(self.run), "cells_*.csv"
        if not meshes:
            print(f"{PROGRAM}: no mesh drawn (no VTU and no cells_*.csv; "
                  "set Output/Write vtu = true)")
            return
        xs = [x for cells, _ in meshes.values() for c in cells for x, _ in c]
        ys = [y for cells, _ in meshes.values() for c in cells for _, y in c]
        aspect = (max(ys) - min(ys)) / max(max(xs) - min(xs), 1e-300)
        fig, ax = self.plt.subplots(figsize=(9, min(9., max(2.8, 7.5 * aspect + 1.2))))
        values = [v for _, fields in meshes.values() for v in fields.get("von_mises", [])]
        low, high = (min(values), max(values)) if values else (0, 1)
        coll = None
        n_cells = 0
        for body, (cells, fields) in meshes.items():
            coll = PolyCollection(cells, edgecolors="k", linewidths=0.15,
                                  cmap="viridis")
            if "von_mises" in fields:
                coll.set_array(fields["von_mises"])
                coll.set_clim(low, high)
            else:
                coll.set_facecolor("none")
            ax.add_collection(coll)
            n_cells += len(cells)
        ax.autoscale_view()
        ax.set_aspect("equal")
        ax.set_xlabel(f"$x_1$ {self.length}")
        ax.set_ylabel(f"$x_2$ {self.length}")
        if values:
            fig.colorbar(coll, ax=ax, shrink=0.8,
                         label=f"von Mises stress {self.stress}")
        ax.set_title(f"last mesh of {', '.join(meshes)}: {n_cells} cells "
                     f"(from the {source})", fontsize=9)
        self.save(fig, "mesh.png")


def units_of(run, option):
    if option:
        parts = [p.strip() for p in option.split(",")]
        if len(parts) != 2 or not all(parts):
            raise RunError(f"--units '{option}': give LENGTH,STRESS, e.g. cm,MPa")
        return tuple(parts)
    units = run.summary.get("units")
    if isinstance(units, dict) and units.get("length") and units.get("stress"):
        return units["length"], units["stress"]
    return "length", "stress"


def main(argv):
    parser = argparse.ArgumentParser(prog=PROGRAM, description=__doc__.split("\n")[0])
    parser.add_argument("outdir", help="the output directory of a run")
    parser.add_argument("--out", metavar="DIR",
                        help="where the PNG (and hertz_<pair>.json) files go "
                             "(default OUTDIR)")
    parser.add_argument("--units", metavar="LENGTH,STRESS",
                        help="units for the axis labels, e.g. cm,MPa "
                             "(default: summary.json's, else none)")
    parser.add_argument("--hertz", choices=("auto", "on", "off"), default="auto",
                        help="draw the Hertz closed form over a pair's pressure: "
                             "auto (default) where the gap is a parabola, both "
                             "materials are known and the half-width a is at "
                             "most 0.1 of the zone and body size (half-plane); "
                             "on without the size test; off never")
    parser.add_argument("--symmetry", choices=("auto", "half", "full"),
                        default="auto",
                        help="whether the run models a whole Hertz contact or "
                             "a half cut on its symmetry line (then the closed "
                             "form takes twice the computed force): auto "
                             "(default) finds a half model from a contact zone "
                             "ending at the parabola's vertex together with a "
                             "roller u_1 = 0 there; half or full say so "
                             "(plane strain only: ignored in axisymmetry, "
                             "where the ring force is the whole force)")
    parser.add_argument("--dpi", type=int, default=110,
                        help="resolution of the PNG files (default 110)")
    args = parser.parse_args(argv)
    try:
        run = Run(args.outdir)
        try:
            import matplotlib
            del matplotlib  # only whether it imports
        except ImportError:
            raise RunError("matplotlib is missing (Debian: apt-get install "
                           "python3-matplotlib)")
        out = args.out or args.outdir
        os.makedirs(out, exist_ok=True)
        plotter = Plotter(run, out, units_of(run, args.units), args.hertz, args.dpi,
                           args.symmetry)
        for draw in (plotter.contact, plotter.convergence,
                     plotter.force_displacement, plotter.load_path,
                     plotter.adaptation, plotter.mesh):
            draw()
    except (RunError, OSError) as e:
        print(f"{PROGRAM}: error: {e}", file=sys.stderr)
        return 1
    for path in plotter.written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
