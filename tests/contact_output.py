#!/usr/bin/env python3
# DESCRIPTION: the ParaView output of a run read back: the contact zone's VTU
# (contact_<pair>-NNNN.vtu) against the uniaxial closed form and against
# contact_<pair>.csv, its active flag against the pressure, the augmented
# Lagrangian's multiplier against the law (20), the smoothed stresses of the
# bodies' VTU against the uniform stress, and the last iterate of a failed
# run. Read by a small reader of deal.II's VTU (base64 + zlib), or with
# --reader paraview by ParaView's own reader (run under pvpython).
"""Run small contact scenes with VTU output and check what ParaView reads."""

import argparse
import base64
import csv
import json
import os
import struct
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
import zlib

FAILURES = []


def check(ok, what):
    print(("  ok    " if ok else "  FAIL  ") + what)
    if not ok:
        FAILURES.append(what)


def check_error(what, error, tolerance):
    ok = error <= tolerance
    print("  %-62s error %.2e%s" % (what, error, "  ok" if ok else "  FAIL"))
    if not ok:
        FAILURES.append(what)


# ---------------------------------------------------------------- readers

TYPES = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
         "UInt8": "B", "UInt32": "I", "UInt64": "Q"}


def decode_binary(text, data_type, header_type, compressed):
    """The values of one binary DataArray of a VTU file: base64 of a header
    (block count, block size, last block size, compressed sizes) and, encoded
    separately, the zlib blocks (VTK's layout, which deal.II writes)."""
    text = "".join(text.split())
    h = TYPES[header_type]
    size = struct.calcsize(h)
    if not compressed:
        raw = base64.b64decode(text)
        n = struct.unpack("<" + h, raw[:size])[0]
        data = raw[size:size + n]
    else:
        first = base64.b64decode(text[:((size + 2) // 3) * 4])
        n_blocks = struct.unpack("<" + h, first[:size])[0]
        header_bytes = (3 + n_blocks) * size
        header_chars = ((header_bytes + 2) // 3) * 4
        header = struct.unpack("<%d%s" % (3 + n_blocks, h),
                               base64.b64decode(text[:header_chars]))
        raw = base64.b64decode(text[header_chars:])
        data, offset = b"", 0
        for length in header[3:]:
            data += zlib.decompress(raw[offset:offset + length])
            offset += length
    t = TYPES[data_type]
    return list(struct.unpack("<%d%s" % (len(data) // struct.calcsize(t), t),
                              data))


def read_vtu_builtin(path):
    """Points, point data and cells (lists of point indices) of an
    unstructured grid written by deal.II."""
    root = ElementTree.parse(path).getroot()
    header_type = root.get("header_type", "UInt32")
    compressed = root.get("compressor") is not None

    def values(array):
        if array.get("format") == "ascii":
            return [float(v) for v in array.text.split()]
        return decode_binary(array.text, array.get("type"), header_type,
                             compressed)

    piece = root.find("UnstructuredGrid/Piece")
    coordinates = values(piece.find("Points/DataArray"))
    points = [tuple(coordinates[i:i + 3])
              for i in range(0, len(coordinates), 3)]
    data = {}
    for array in piece.findall("PointData/DataArray"):
        v = values(array)
        n = int(array.get("NumberOfComponents", "1"))
        data[array.get("Name")] = v if n == 1 else [
            tuple(v[i:i + n]) for i in range(0, len(v), n)]
    connectivity = values(piece.find("Cells/DataArray[@Name='connectivity']"))
    offsets = values(piece.find("Cells/DataArray[@Name='offsets']"))
    cells = [connectivity[int(begin):int(end)]
             for begin, end in zip([0] + offsets[:-1], offsets)]
    return points, data, cells


def read_vtu_paraview(path):
    """The same through ParaView's reader (under pvpython)."""
    from paraview import servermanager
    from paraview.simple import XMLUnstructuredGridReader
    grid = servermanager.Fetch(XMLUnstructuredGridReader(FileName=[path]))
    points = [grid.GetPoint(i) for i in range(grid.GetNumberOfPoints())]
    data = {}
    point_data = grid.GetPointData()
    for a in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(a)
        n = array.GetNumberOfComponents()
        data[array.GetName()] = [
            array.GetTuple(i) if n > 1 else array.GetTuple(i)[0]
            for i in range(array.GetNumberOfTuples())]
    cells = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        cells.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    return points, data, cells


READ_VTU = read_vtu_builtin


def pvd_files(path):
    """The files of a .pvd collection, in its order."""
    root = ElementTree.parse(path).getroot()
    return [d.get("file") for d in root.iter("DataSet")]


def place(x):
    """A point's key: its coordinates to 1e-5 (the zones' points lie
    further apart)."""
    return (round(x[0], 5), round(x[1], 5))


def contact_points(path):
    """The distinct points of a contact zone's VTU (each point appears once
    per line cell it ends) with their fields."""
    points, data, _ = READ_VTU(path)
    seen = {}
    for i, x in enumerate(points):
        if place(x) not in seen:
            seen[place(x)] = {name: values[i] for name, values in data.items()}
            seen[place(x)]["x"] = x
    return list(seen.values())


def is_one_chain(path):
    """Whether the line cells of a zone join its points into one open
    chain: n - 1 cells, no point in more than two, all connected."""
    points, _, cells = READ_VTU(path)
    neighbours = {}
    for cell in cells:
        a, b = (place(points[i]) for i in cell)
        neighbours.setdefault(a, set()).add(b)
        neighbours.setdefault(b, set()).add(a)
    reached, front = set(), [next(iter(neighbours))]
    while front:
        p = front.pop()
        if p not in reached:
            reached.add(p)
            front.extend(neighbours[p])
    return (len(cells) == len(neighbours) - 1 and reached == set(neighbours)
            and all(len(n) <= 2 for n in neighbours.values()))


# ---------------------------------------------------------------- runs

def run(args, scene, out, sets, must_succeed=True):
    command = [args.exe, os.path.join(args.source, scene), "--output", out]
    for s in sets:
        command += ["--set", s]
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    if must_succeed and result.returncode != 0:
        print(result.stdout)
        raise SystemExit("FAILED: " + " ".join(command))
    return result


def check_uniaxial(args):
    """prm/stability/uniaxial.prm: a uniform pressure p on S (closed form
    of the penalised problem (15)), a linear displacement, a uniform
    stress."""
    out = os.path.join(args.out, "uniaxial")
    run(args, "prm/stability/uniaxial.prm", out, ["Output/Write vtu=true"])
    Delta, E, nu, H1, H2, c = 1.366e-3, 2.1e5, 0.3, 1.0, 1.0, 0.05
    theta = c * H1 / E
    p = Delta / ((1 - nu**2) * (H1 / E + H2 / E) + theta)
    print("uniaxial: closed form p = %.10g, theta = %.6g" % (p, theta))

    check(pvd_files(os.path.join(out, "contact_S.pvd")) ==
          ["contact_S-0000.vtu"], "contact_S.pvd lists the one step")
    zone = contact_points(os.path.join(out, "contact_S-0000.vtu"))
    check(len(zone) > 0, "the zone has points (%d)" % len(zone))
    # The VTU holds Float32 (relative round-off 6e-8); the DD stops at a
    # relative residual of 1e-10 with a condition of ~40 (augmented_
    # lagrangian.cc): 1e-6 bounds both, 1e-5 for the penetration, a
    # difference of displacements ~40 times larger than itself.
    check_error("pressure = closed form p",
                max(abs(z["pressure"] - p) for z in zone) / p, 1e-6)
    check_error("penetration = theta p (the penalty's overlap)",
                max(abs(z["penetration"] - theta * p) for z in zone) /
                (theta * p), 1e-5)
    check(all(z["active"] == 1 for z in zone), "every point active")
    # u_1 on S_1 (x2 = H2): sigma_22 = -p, sigma_11 = 0, plane strain,
    # top moved by -Delta, left side on rollers: u_2 = -Delta + (1 - nu^2)
    # p H1/E, u_1 = nu (1 + nu) p x1 / E.
    u2 = -Delta + (1 - nu**2) * p * H1 / E
    check_error("displacement_y of body 1 on S_1 = closed form",
                max(abs(z["displacement"][1] - u2) for z in zone) / Delta,
                1e-6)
    check_error("displacement_x of body 1 on S_1 = closed form",
                max(abs(z["displacement"][0] - nu * (1 + nu) * p *
                        z["x"][0] / E) for z in zone) / Delta, 1e-6)

    # Smoothed stresses: the projection of the uniform stress is that
    # stress (to the Float32 of the file).
    for body in ["omega1", "omega2"]:
        _, data, _ = READ_VTU(os.path.join(out, body + "-0000.vtu"))
        exact = {"sigma_11_smoothed": 0, "sigma_22_smoothed": -p,
                 "sigma_12_smoothed": 0, "sigma_33_smoothed": -nu * p,
                 "von_mises_smoothed": p * (1 - nu + nu**2)**0.5}
        check(all(name in data for name in exact),
              body + ": the VTU has the smoothed stresses")
        for name, value in exact.items():
            check_error(body + ": " + name + " = uniform stress",
                        max(abs(v - value) for v in data.get(name, [1e300]))
                        / p, 1e-6)


def check_paper_scene(args):
    """The paper's scene on fixed coarse meshes with the augmented
    Lagrangian: a partial contact, so the active flag takes both values;
    the VTU against contact_S.csv and against the law (20)."""
    out = os.path.join(args.out, "paper")
    run(args, "prm/paper_two_bodies.prm", out,
        ["Output/Write vtu=true", "Adaptation/Mode=none",
         "Body omega1/Mesh/Initial refinement=1",
         "Contact solver/Domain decomposition/Relaxation=anderson",
         "Contact solver/Tolerance=1e-10",
         "Contact pair S/Formulation=exact",
         # the Uzawa loop's floor on these non-matching meshes is 1.02e-3
         "Contact solver/Uzawa/Tolerance=2e-3"])
    summary = json.load(open(os.path.join(out, "summary.json")))
    theta = summary["theta"][0]
    zone = contact_points(os.path.join(out, "contact_S-0000.vtu"))
    with open(os.path.join(out, "contact_S.csv")) as f:
        rows = list(csv.DictReader(f))
    peak = max(float(r["pressure"]) for r in rows)
    print("paper scene: %d contact points, peak pressure %.6g" %
          (len(rows), peak))

    check(len(zone) == len(rows), "one VTU point per contact point of the "
          "CSV (%d, %d)" % (len(zone), len(rows)))
    check(is_one_chain(os.path.join(out, "contact_S-0000.vtu")),
          "the line cells join the points into one chain along S_1")
    by_place = {place(z["x"]): z for z in zone}
    worst = {"pressure": 0, "u_1n": 0, "u_2n": 0, "gap": 0}
    scale = {"pressure": peak,
             "u_1n": max(abs(float(r["u_1n"])) for r in rows),
             "u_2n": max(abs(float(r["u_2n"])) for r in rows),
             "gap": max(abs(float(r["gap"])) for r in rows)}
    missing = 0
    for r in rows:
        z = by_place.get(place((float(r["x1"]), float(r["x2"]))))
        if z is None:
            missing += 1
            continue
        for name in worst:
            worst[name] = max(worst[name],
                              abs(z[name] - float(r[name])) / scale[name])
    check(missing == 0, "every CSV point is a VTU point")
    # The CSV has 12 digits, the VTU Float32.
    for name, error in worst.items():
        check_error(name + " = contact_S.csv", error, 1e-6)

    active = [z for z in zone if z["active"] == 1]
    check(0 < len(active) < len(zone),
          "partial contact: %d of %d points active" % (len(active), len(zone)))
    check(all((z["active"] == 1) == (z["pressure"] > 0) for z in zone),
          "active flag = (pressure > 0) at every point")
    check_error("peak pressure = summary.json max_pressure",
                abs(max(z["pressure"] for z in zone) -
                    summary["contact"][0]["max_pressure"]) / peak, 1e-6)
    # (20) with the multiplier: pressure = max(0, -lambda + (u_1n + u_2n -
    # f_n)/theta); penetration/theta carries the Float32 of the
    # penetration, ~1e-7 of the peak.
    check("multiplier" in zone[0], "the VTU has the AL multiplier")
    check_error("pressure = max(0, multiplier + penetration/theta)",
                max(abs(z["pressure"] - max(0., z.get("multiplier", 1e300) +
                                            z["penetration"] / theta))
                    for z in zone) / peak, 1e-5)


def check_failed_run(args):
    """A run stopped at Max iterations writes its last iterate, the contact
    zone too."""
    out = os.path.join(args.out, "failed")
    result = run(args, "prm/stability/uniaxial.prm", out,
                 ["Output/Write vtu=true",
                  "Contact solver/Max iterations=2"],
                 must_succeed=False)
    check(result.returncode != 0, "the run stops at Max iterations")
    check(os.path.exists(os.path.join(out, "contact_S-0000.vtu")) and
          pvd_files(os.path.join(out, "contact_S.pvd")) ==
          ["contact_S-0000.vtu"],
          "its last iterate's contact zone is written")


def main():
    global READ_VTU
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--exe", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--reader", choices=["builtin", "paraview"],
                        default="builtin")
    args = parser.parse_args()
    if args.reader == "paraview":
        READ_VTU = read_vtu_paraview
    os.makedirs(args.out, exist_ok=True)
    check_uniaxial(args)
    check_paper_scene(args)
    check_failed_run(args)
    print("PASSED" if not FAILURES else "FAILED")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
