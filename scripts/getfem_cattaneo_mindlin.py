#!/usr/bin/python3
"""The Cattaneo-Mindlin scene of prm/cattaneo_mindlin.prm solved with
GetFEM (python3-getfem, GetFEM 5.4) on given Gmsh meshes of the two blocks
(scripts/cattaneo_mindlin_meshes.py), for doc/friction.md section 5.6.

    /usr/bin/python3 scripts/getfem_cattaneo_mindlin.py UPPER.msh LOWER.msh
        OUT.csv [--variant nodal|mortar] [--r R] [--max-res TOL]

Scene: E = 1000, nu = 0.3, plane strain; the upper block [-10,10]x[0,10]
(its bottom, physical tag 2, is the contact line; its top, tag 3, is
moved), the lower block [-10,10]x[-10,0] (its bottom, tag 2, is held; its
top, tag 3, is the contact line). Initial gap g(x) = x^2 / (2R), R = 50,
as data (the meshes are flat). Coulomb friction mu = 0.3, exact contact
(Lagrange multipliers). Load step 1 moves the top by (0, -Delta), step 2 by
(U, -Delta), Delta = 0.005, U = 0.0015.

GetFEM side: both blocks are read with gf.Mesh('import', 'gmsh', ...);
the lower one is translated by (0, -OFFSET) before the two are merged into
one mesh, so that GetFEM keeps the coincident nodes of y = 0 apart
(Mesh.merge joins coincident points; linear elasticity does not see the
translation). Q1 elements (FEM_QK(2,1)), 2x2 Gauss. The contact is GetFEM's
basic contact brick with Coulomb friction (add_basic_contact_brick,
non-symmetric Alart-Curnier augmented Lagrangian), whose matrices BN, BT
and gap vector are built here for the node pairs (x_i, 0) of the two
blocks (the meshes match on y = 0):
- variant nodal (node to node, GetFEM's nodal contact): row i of BN is the
  approach u_2y - u_1y at node i, of BT the slip u_1x - u_2x, and the gap
  g(x_i);
- variant mortar (weighted nodal conditions, the averages over the hat
  function psi_i of the line): row i is (1/m_i) int psi_i (...) with
  m_i = int psi_i, the gap (1/m_i) int psi_i I_h g.
The quasi-static friction law of step 2 acts on the slip since step 1:
the brick's data wt is the displacement of step 1 and gamma = 1 (the
slip in the law is BT (u - wt)).

Tractions at the nodes (columns pressure, tangential_traction): in the
nodal variant the multipliers are nodal forces, and the traction of node
i is its force over m_i (lumped); in the mortar variant lambda_i / m_i is
the nodal value of the traction t_h = sum_i t_i psi_i whose work
int t_h psi_j gives the nodal forces (as ddcontact's nodal multipliers).
The columns *_consistent hold M^-1 f, the L2 representative of the nodal
forces f with the line's mass matrix M (for the mortar variant the same
values). Sign convention of ddcontact (doc/output.md):
pressure >= 0, and tangential_traction t with the traction -t e_x on the
upper block (t > 0 under the shear U > 0).

Writes OUT.csv (one row per node of the contact line, sorted by x) and
OUT.json (P, Q, unknowns, Newton steps, residuals, times).
"""
import argparse
import json
import math
import os
import sys
import time

T_START = time.perf_counter()

import numpy as np  # noqa: E402
import getfem as gf  # noqa: E402

E, NU = 1000.0, 0.3
R_CURV, DELTA, U_SHEAR, MU = 50.0, 0.005, 0.0015, 0.3
OFFSET = 100.0  # translation of the lower block inside GetFEM's mesh


def line_mass(xs):
    """The P1 mass matrix of the nodes xs (sorted) of a line, dense."""
    n = len(xs)
    M = np.zeros((n, n))
    for k in range(n - 1):
        h = xs[k + 1] - xs[k]
        M[k, k] += h / 3
        M[k + 1, k + 1] += h / 3
        M[k, k + 1] += h / 6
        M[k + 1, k] += h / 6
    return M


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("upper")
    ap.add_argument("lower")
    ap.add_argument("out")
    ap.add_argument("--variant", choices=["nodal", "mortar"], default="nodal")
    ap.add_argument("--r", type=float, default=E,
                    help="augmentation parameter r of the brick (default E)")
    ap.add_argument("--max-res", type=float, default=1e-9,
                    help="GetFEM Newton tolerance (its residual is scaled "
                    "by that of the first iterate; round-off floor ~2e-11)")
    ap.add_argument("--max-iter", type=int, default=100)
    ap.add_argument("--lsolver", default="auto")
    ap.add_argument("--noisy", action="store_true",
                    help="print GetFEM's Newton residuals")
    args = ap.parse_args()

    m = gf.Mesh("import", "gmsh", args.upper)
    lower = gf.Mesh("import", "gmsh", args.lower)
    lower.translate([0.0, -OFFSET])
    m.merge(lower)
    big = 1e3
    # Regions by geometry (the tags 2 and 3 of the files are the same
    # lines): the top of the upper block and the bottom of the lower one.
    TOP, BOTTOM = 1, 2
    m.set_region(TOP, m.outer_faces_in_box([-big, 10 - 1e-9],
                                           [big, 10 + 1e-9]))
    m.set_region(BOTTOM, m.outer_faces_in_box(
        [-big, -OFFSET - 10 - 1e-9], [big, -OFFSET - 10 + 1e-9]))

    mfu = gf.MeshFem(m, 2)
    mfu.set_fem(gf.Fem("FEM_QK(2,1)"))
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,2)"))
    nd = mfu.nbdof()
    P = mfu.basic_dof_nodes()
    # Interleaved components: dof 2k is x, 2k+1 is y of the same node.
    assert np.allclose(P[:, 0::2], P[:, 1::2])
    xn, yn = P[0, 0::2], P[1, 0::2]
    up = np.where(np.abs(yn) < 1e-12)[0]
    lo = np.where(np.abs(yn + OFFSET) < 1e-9)[0]
    up = up[np.argsort(xn[up])]
    lo = lo[np.argsort(xn[lo])]
    xs = xn[up]
    if len(up) != len(lo) or np.max(np.abs(xn[lo] - xs)) > 1e-12:
        sys.exit("the two contact lines do not have the same nodes")
    nbc = len(xs)

    # Node-to-node rows, then the weighted (mortar) ones.
    gap_nodes = xs ** 2 / (2 * R_CURV)
    M = line_mass(xs)
    m_i = M.sum(axis=1)
    W = np.eye(nbc) if args.variant == "nodal" else M / m_i[:, None]
    gap = W @ gap_nodes
    BN = gf.Spmat("empty", nbc, nd)
    BT = gf.Spmat("empty", nbc, nd)
    for i in range(nbc):
        for j in np.nonzero(W[i])[0]:
            w = float(W[i, j])
            BN.add(i, 2 * int(lo[j]) + 1, w)     # approach u_2y - u_1y
            BN.add(i, 2 * int(up[j]) + 1, -w)
            BT.add(i, 2 * int(up[j]), w)         # slip u_1x - u_2x
            BT.add(i, 2 * int(lo[j]), -w)

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu_lame = E / (2 * (1 + NU))
    md.add_initialized_data("lambda", [lam])   # 2D Lame = plane strain
    md.add_initialized_data("mu", [mu_lame])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")
    md.add_initialized_data("top", [0.0, -DELTA])
    md.add_Dirichlet_condition_with_simplification("u", TOP, "top")
    md.add_initialized_data("bottom", [0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("u", BOTTOM, "bottom")
    md.add_variable("lambda_n", nbc)
    md.add_variable("lambda_t", nbc)
    md.add_initialized_data("r", [args.r])
    md.add_initialized_data("fr", [MU])
    md.add_initialized_data("gap", gap)
    md.add_initialized_data("alpha", np.ones(nbc))
    md.add_initialized_data("gamma", [1.0])
    md.add_initialized_data("wt", np.zeros(nd))
    md.add_basic_contact_brick("u", "lambda_n", "lambda_t", "r", BN, BT,
                               "fr", "gap", "alpha", 1, "gamma", "wt")

    def residual():
        md.assembly("build_rhs")
        return float(np.linalg.norm(md.rhs()))

    t_setup = time.perf_counter() - T_START
    steps, solve_time = [], 0.0
    for step, shear in ((1, 0.0), (2, U_SHEAR)):
        md.set_variable("top", [shear, -DELTA])
        if step == 2:
            md.set_variable("wt", md.variable("u"))
        t0 = time.perf_counter()
        nit, converged = md.solve("max_res", args.max_res,
                                  "max_iter", args.max_iter,
                                  "lsolver", args.lsolver,
                                  "lsearch", "default",
                                  *(["noisy"] if args.noisy else []))
        solve_time += time.perf_counter() - t0
        ln = np.array(md.variable("lambda_n"))
        lt = np.array(md.variable("lambda_t"))
        steps.append({"step": step, "newton_steps": int(nit),
                      "converged": bool(converged), "residual": residual(),
                      "P": float(-ln.sum()), "Q": float(abs(lt.sum()))})

    ln = np.array(md.variable("lambda_n"))
    lt = np.array(md.variable("lambda_t"))
    # lambda_n <= 0 in contact: the normal force pair i carries is
    # -lambda_n[i], spread on the nodes by the row weights W[i, j]. The
    # tangential multiplier acts against the slip u_1x - u_2x, so the
    # traction on the upper block is +lambda_t e_x, i.e. t = -lambda_t in
    # ddcontact's convention (-t e_x on the upper block).
    fn = -ln
    ft = -lt
    # Nodal forces on the upper block: W^T times the multipliers.
    fn_nodes = W.T @ fn
    ft_nodes = W.T @ ft
    if args.variant == "nodal":
        # Node to node: the multipliers are the nodal forces; the traction
        # of node i is its force over int psi_i (lumped).
        p_nodes, t_nodes = fn_nodes / m_i, ft_nodes / m_i
    else:
        # Weighted rows: the forces are int t_h psi_j with t_h = sum_i
        # (lambda_i / m_i) psi_i, so lambda_i / m_i is the traction's nodal
        # value (as the nodal multipliers of ddcontact).
        p_nodes, t_nodes = fn / m_i, ft / m_i
    # The L2 representative of the nodal forces: M t = f (for the mortar
    # variant the same as above).
    p_cons = np.linalg.solve(M, fn_nodes)
    t_cons = np.linalg.solve(M, ft_nodes)
    Pn, Qt = float(fn.sum()), float(ft.sum())

    total = time.perf_counter() - T_START
    base = os.path.splitext(args.out)[0]
    with open(args.out, "w") as f:
        f.write("x,pressure,tangential_traction,pressure_consistent,"
                "tangential_traction_consistent,force_n,force_t,weight,"
                "gap\n")
        for k in range(nbc):
            f.write(f"{xs[k]:.15g},{p_nodes[k]:.15g},{t_nodes[k]:.15g},"
                    f"{p_cons[k]:.15g},{t_cons[k]:.15g},{fn_nodes[k]:.15g},"
                    f"{ft_nodes[k]:.15g},{m_i[k]:.15g},{gap_nodes[k]:.15g}\n")
    summary = {
        "code": "getfem-" + args.variant,
        "getfem_version": getattr(gf, "__version__", "5.4"),
        "upper": os.path.abspath(args.upper),
        "lower": os.path.abspath(args.lower),
        "P": Pn, "Q": Qt,
        "displacement_unknowns": int(nd), "contact_unknowns": 2 * nbc,
        "unknowns": int(nd) + 2 * nbc, "contact_nodes": nbc,
        "r": args.r, "max_res": args.max_res,
        "steps": steps,
        "newton_steps": sum(s["newton_steps"] for s in steps),
        "converged": all(s["converged"] for s in steps),
        "final_residual": steps[-1]["residual"],
        "time_setup": t_setup, "time_solve": solve_time,
        "time_total": total,
    }
    with open(base + ".json", "w") as f:
        json.dump(summary, f, indent=1)
    print(json.dumps({k: v for k, v in summary.items() if k != "steps"}))
    for s in steps:
        print(s)


if __name__ == "__main__":
    main()
