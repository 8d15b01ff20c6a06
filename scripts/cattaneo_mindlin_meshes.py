#!/usr/bin/env python3
"""Conforming, graded Q1 meshes of the Cattaneo-Mindlin blocks of
prm/cattaneo_mindlin.prm for the GetFEM comparison
(scripts/friction_getfem_study.py, doc/friction.md section 5.6).

Both blocks are tensor-product meshes of the same node lines:
- x: uniform spacing h on |x| <= L (L >= 0.45, a whole number of cells),
  then cells growing by the ratio q up to |x| = 10 (the graded part is
  scaled so that it ends exactly at 10);
- y: the same on 0 <= |y| <= 10 (uniform h down to the depth L, then
  graded). The lower block is the mirror image of the upper one, so the
  nodes of both sides of y = 0 have the same x.

Written as Gmsh 2.2 ASCII files, one per block, with the physical tags
ddcontact takes as boundary ids: 2 on the bottom (y = min) and 3 on the
top (y = max); the sides get no line elements (deal.II gives them id 0);
the cells carry the physical tag 100.

    scripts/cattaneo_mindlin_meshes.py H OUTDIR   (writes upper.msh, lower.msh)
"""
import math
import os
import sys

ZONE = 0.45      # half-width (and depth) of the uniformly fine part
SIZE = 10.0      # half-width and height of each block
GROWTH = 1.2     # size ratio of neighbouring cells outside the fine part


def graded_coordinates(h, zone=ZONE, size=SIZE, growth=GROWTH):
    """The node coordinates 0 = s_0 < ... < s_n = size: spacing h up to the
    first multiple of h at or beyond zone, then growing by `growth`."""
    n_fine = int(math.ceil(zone / h - 1e-9))
    fine = [k * h for k in range(n_fine + 1)]
    rest = size - fine[-1]
    steps, width, dh = [], 0.0, h
    while width < rest:
        dh *= growth
        steps.append(dh)
        width += dh
    # Scale the graded steps so that they end exactly at `size`; drop the
    # last one when that leaves the first graded cell smaller than h.
    if len(steps) > 1 and (rest / (width - steps[-1])) * steps[0] >= h:
        width -= steps.pop()
    scale = rest / width
    s = fine[:]
    for dh in steps:
        s.append(s[-1] + dh * scale)
    s[-1] = size
    return s


def mesh_lines(h):
    """x node positions (symmetric about 0) and the upper block's y
    positions (0 to 10)."""
    half = graded_coordinates(h)
    xs = [-v for v in reversed(half[1:])] + half
    return xs, half


def write_msh(path, xs, ys, bottom_tag=2, top_tag=3):
    """A structured quadrilateral mesh of the node lines xs x ys (both
    increasing) in the Gmsh 2.2 ASCII format; cells counter-clockwise."""
    nx, ny = len(xs), len(ys)

    def node(i, j):
        return 1 + j * nx + i

    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes",
             str(nx * ny)]
    for j in range(ny):
        for i in range(nx):
            lines.append(f"{node(i, j)} {xs[i]:.17g} {ys[j]:.17g} 0")
    lines.append("$EndNodes")
    elements = []
    for i in range(nx - 1):   # bottom and top edges
        elements.append((1, bottom_tag, (node(i, 0), node(i + 1, 0))))
    for i in range(nx - 1):
        elements.append((1, top_tag, (node(i + 1, ny - 1), node(i, ny - 1))))
    for j in range(ny - 1):
        for i in range(nx - 1):
            elements.append((3, 100, (node(i, j), node(i + 1, j),
                                      node(i + 1, j + 1), node(i, j + 1))))
    lines += ["$Elements", str(len(elements))]
    for k, (etype, tag, nodes) in enumerate(elements, 1):
        lines.append(f"{k} {etype} 2 {tag} {tag} " +
                     " ".join(str(n) for n in nodes))
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_pair(h, outdir):
    """upper.msh ([-10,10] x [0,10]) and lower.msh ([-10,10] x [-10,0]) in
    outdir; returns (paths, number of x nodes, number of y nodes)."""
    os.makedirs(outdir, exist_ok=True)
    xs, ys = mesh_lines(h)
    upper = os.path.join(outdir, "upper.msh")
    lower = os.path.join(outdir, "lower.msh")
    write_msh(upper, xs, ys, bottom_tag=2, top_tag=3)
    write_msh(lower, xs, [-v for v in reversed(ys)], bottom_tag=2, top_tag=3)
    return (upper, lower), len(xs), len(ys)


if __name__ == "__main__":
    (u, l), nx, ny = write_pair(float(sys.argv[1]), sys.argv[2])
    print(u, l, f"{nx} x {ny} nodes per block,",
          4 * nx * ny, "displacement unknowns")
