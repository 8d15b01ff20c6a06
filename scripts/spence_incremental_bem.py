#!/usr/bin/env python3
"""
Independent check of spence_stick_ratio.py (doc/axisymmetric.md, the test
spence_sphere): incremental (load-stepped) boundary-element
simulation of monotonic Hertz loading with Coulomb friction, Goodman
approximation (pressure = Hertz, only the tangential problem is solved).

Relative tangential displacement (normalised by sum (1-nu_i)/G_i):
    ubar(x) = sum_j C_ij q_j - beta * Fp(x; a)
  axisymmetric: C_ij = int_elem_j s H(r_i,s) ds,  H = (1/2pi) int cos(th)/rho dth
                (ring kernel from Cerruti point-force solution; the nu-dependent
                 part integrates to zero around the ring)
                Fp = (1/r) int_0^r s p(s) ds
  plane strain: C_ij = (1/pi) int_elem_j ln|(x+s)/(x-s)| ds  (odd q)
                Fp = int_0^x p(s) ds
Hertz pressure p = sqrt(a^2 - r^2) (p0 proportional to a).
Friction: stick -> ubar frozen over the step, |q| <= mu p;
          slip  -> q = -mu p sign(d ubar).
The stick/slip boundary at the final step gives c/a (resolution 1/N).
Nothing here uses the self-similar analysis.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from spence_stick_ratio import ellipke, c_over_a_sphere, c_over_a_cylinder


def gauss_legendre(n):
    xs, ws = [], []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-15:
                break
        xs.append(x)
        ws.append(2 / ((1 - x * x) * dp * dp))
    return xs, ws


GX, GW = gauss_legendre(24)


def ring_H(r, s):
    """(1/2pi) int_0^{2pi} cos(th)/rho dth = int_0^inf J1(xr)J1(xs) dx."""
    k = 2 * math.sqrt(r * s) / (r + s)
    kc = abs(r - s) / (r + s)
    K, E = ellipke(k, kc)
    return ((2 - k * k) * K - 2 * E) / (k * math.pi * math.sqrt(r * s))


def quad_sing(f, A, B):
    """int_A^B f, f (log-)singular at A: s = A + (B-A) w^2."""
    tot = 0.0
    for x, w in zip(GX, GW):
        u = 0.5 * (x + 1)
        s = A + (B - A) * u * u
        tot += w * 0.5 * f(s) * 2 * (B - A) * u
    return tot


def kernel_axi(N):
    h = 1.0 / N
    r = [(i + 0.5) * h for i in range(N)]
    C = [[0.0] * N for _ in range(N)]
    for i in range(N):
        ri = r[i]
        f = lambda s: s * ring_H(ri, s)
        for j in range(N):
            a0, b0 = j * h, (j + 1) * h
            if a0 < ri < b0:
                C[i][j] = quad_sing(f, ri, a0) * -1 + quad_sing(f, ri, b0)
            elif abs(ri - a0) <= abs(ri - b0):
                C[i][j] = quad_sing(f, a0, b0)
            else:
                C[i][j] = -quad_sing(f, b0, a0)
    return r, C


def kernel_2d(N):
    h = 1.0 / N
    x = [(i + 0.5) * h for i in range(N)]
    F = lambda y: 0.0 if y == 0 else y * math.log(abs(y)) - y
    C = [[0.0] * N for _ in range(N)]
    for i in range(N):
        for j in range(N):
            sa, sb = j * h, (j + 1) * h
            xi = x[i]
            C[i][j] = (F(xi + sb) - F(xi + sa) + F(xi - sb) - F(xi - sa)) / math.pi
    return x, C


def Fp_axi(r, a):
    if r < a:
        return (a ** 3 - (a * a - r * r) ** 1.5) / (3 * r)
    return a ** 3 / (3 * r)


def Fp_2d(x, a):
    if x < a:
        return 0.5 * (x * math.sqrt(a * a - x * x) + a * a * math.asin(x / a))
    return math.pi * a * a / 4


def solve_dense(A, b):
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(A)]
    for c in range(n):
        p = max(range(c, n), key=lambda i: abs(M[i][c]))
        M[c], M[p] = M[p], M[c]
        piv = M[c][c]
        for i in range(c + 1, n):
            f = M[i][c] / piv
            if f:
                Mi, Mc = M[i], M[c]
                for k in range(c, n + 1):
                    Mi[k] -= f * Mc[k]
    xs = [0.0] * n
    for i in range(n - 1, -1, -1):
        s = M[i][n] - sum(M[i][k] * xs[k] for k in range(i + 1, n))
        xs[i] = s / M[i][i]
    return xs


def simulate(geom, ratio, N=60, steps=60, C=None, x=None):
    mu, beta = 1.0, ratio
    Fp = Fp_axi if geom == "axi" else Fp_2d
    q = [0.0] * N
    # status: 0 out of contact, 1 stick, +2/-2 slip with q = sign*mu*p
    st = [0] * N
    ub_prev = [0.0] * N          # relative tangential displacement
    for n in range(1, steps + 1):
        a = n / steps
        p = [math.sqrt(a * a - xi * xi) if xi < a else 0.0 for xi in x]
        Fn = [Fp(xi, a) for xi in x]
        for i in range(N):
            if p[i] > 0 and st[i] == 0:
                st[i] = 1                      # first guess: stick
        for it in range(200):
            S = [i for i in range(N) if st[i] == 1]
            qn = [0.0] * N
            for i in range(N):
                if abs(st[i]) == 2:
                    qn[i] = (1 if st[i] > 0 else -1) * mu * p[i]
            if S:
                A = [[C[i][j] for j in S] for i in S]
                b = [ub_prev[i] + beta * Fn[i]
                     - sum(C[i][j] * qn[j] for j in range(N) if abs(st[j]) == 2)
                     for i in S]
                qs = solve_dense(A, b)
                for i, v in zip(S, qs):
                    qn[i] = v
            ub = [sum(C[i][j] * qn[j] for j in range(N)) - beta * Fn[i] for i in range(N)]
            changed = False
            # stick nodes violating |q|<=mu p -> slip (worst first is enough)
            worst, wv = None, 0.0
            for i in S:
                ex = abs(qn[i]) - mu * p[i]
                if ex > 1e-12 * (1 + mu * p[i]) and ex > wv:
                    worst, wv = i, ex
            if worst is not None:
                st[worst] = 2 if qn[worst] > 0 else -2
                changed = True
            else:
                # slip nodes slipping the wrong way -> stick
                for i in range(N):
                    if abs(st[i]) == 2:
                        du = ub[i] - ub_prev[i]
                        if (1 if st[i] > 0 else -1) * du > 1e-14:
                            st[i] = 1
                            changed = True
            if not changed:
                break
        q, ub_prev = qn, ub
    stick = [x[i] for i in range(N) if st[i] == 1]
    slip = [x[i] for i in range(N) if abs(st[i]) == 2]
    cmax = max(stick) if stick else 0.0
    smin = min(slip) if slip else 1.0
    # estimate c as midway between last stick node and first slip node
    return 0.5 * (cmax + smin), cmax, smin, st, q


if __name__ == "__main__":
    # kernel sanity check against the ring integral
    r0, s0 = 0.3, 1.0
    n = 20000
    direct = sum(math.cos((i + 0.5) * 2 * math.pi / n) /
                 math.sqrt(r0 * r0 + s0 * s0 - 2 * r0 * s0 * math.cos((i + 0.5) * 2 * math.pi / n))
                 for i in range(n)) / n
    print("ring kernel check:", direct, ring_H(r0, s0))
    N = int(sys.argv[1]) if len(sys.argv) > 1 else 60
    ratios = [float(v) for v in sys.argv[2].split(",")] if len(sys.argv) > 2 else [0.2, 0.5, 1.0, 2.0]
    for geom in ("axi", "2d"):
        x, C = kernel_axi(N) if geom == "axi" else kernel_2d(N)
        for rt in ratios:
            c, cmax, smin, st, q = simulate(geom, rt, N, N, C, x)
            exact = (c_over_a_sphere if geom == "axi" else c_over_a_cylinder)(rt)[0]
            # is the stick zone contiguous from the centre?
            pattern = "".join("S" if s == 1 else ("+" if s == 2 else ("-" if s == -2 else ".")) for s in st)
            print(f"{geom:4s} beta/mu={rt:4.2f}  BEM c/a={c:.4f} (last stick {cmax:.4f}, first slip {smin:.4f})"
                  f"  formula={exact:.4f}")
            print("      ", pattern)
