#!/usr/bin/env python3
"""
Stick-zone size for monotonic normal (Hertz) loading of two dissimilar elastic
bodies with Coulomb friction mu -- the Spence (1975) problem -- under the
Goodman approximation (the shear traction is assumed not to alter the Hertz
pressure), which makes c/a a function of beta/mu only.

Notation: k = c/a (stick radius / contact radius), k' = sqrt(1-k^2),
K(m), E(m) = complete elliptic integrals with MODULUS m,
K(m) = int_0^{pi/2} dth / sqrt(1 - m^2 sin^2 th);  K'(k) := K(k').

  Sphere (axisymmetric):      beta/mu = k K(k') / artanh(k)
                                      = 2 (c/a) K'(c/a) / ln[(a+c)/(a-c)]
  Cylinder (plane strain):    beta/mu = K(k') / K(k) = K'(c/a) / K(c/a)
        i.e. explicitly  c/a = theta2(q)^2 / theta3(q)^2,  q = exp(-pi beta/mu)

Conditions used (doc/axisymmetric.md): self-similarity => in the stick zone the
relative tangential displacement is u = C r|r| (frozen), slip zone q = mu p,
and the traction must be bounded AND join mu*p smoothly (continuous q and
dq/dr) at r = c, because the stick zone advances into the slip zone.

Pure python; no numpy/scipy.
"""
import math


def ellipke(m, mc=None):
    """(K, E) for modulus m by the AGM; mc = sqrt(1-m^2) may be given exactly."""
    if mc is None:
        if m < 0 or m >= 1:
            raise ValueError("modulus must be in [0,1)")
        mc = math.sqrt(1.0 - m * m)
    if mc <= 0:
        raise ValueError("complementary modulus must be > 0")
    a, b, c = 1.0, mc, m
    s, pw = 0.5 * c * c, 0.5
    for _ in range(60):
        if abs(c) < 1e-17:
            break
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        pw *= 2.0
        s += pw * c * c
    K = math.pi / (2.0 * a)
    return K, K * (1.0 - s)


# ---------------------------------------------------------------- sphere
def ratio_sphere_from_kc(kc):
    """beta/mu for the sphere, parametrised by k' = sqrt(1-(c/a)^2) (robust
    when c/a -> 1).  artanh(k) = ln((1+k)/k')."""
    k = math.sqrt(1.0 - kc * kc) if kc > 1e-8 else 1.0 - 0.5 * kc * kc
    Kp = ellipke(kc, k)[0]                 # K(k')
    return k * Kp / math.log((1.0 + k) / kc)


def c_over_a_sphere(ratio):
    """Solve k K(k')/artanh(k) = beta/mu for k=c/a; returns (c/a, 1-c/a)."""
    # the RHS increases monotonically with k' from 0 (k'->0) to inf (k'->1)
    lo, hi = 1e-300, 1.0 - 1e-16
    for _ in range(2000):
        mid = math.sqrt(lo * hi) if hi / lo > 4 else 0.5 * (lo + hi)
        if ratio_sphere_from_kc(mid) < ratio:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15 * hi:
            break
    kc = 0.5 * (lo + hi)
    k = math.sqrt(1.0 - kc * kc)
    return k, kc * kc / (1.0 + k)


# -------------------------------------------------------------- cylinder
def c_over_a_cylinder(ratio):
    """K'(k)/K(k) = beta/mu  <=>  nome q = exp(-pi K'/K) = exp(-pi beta/mu),
    k = theta2^2/theta3^2, k' = theta4^2/theta3^2.  Returns (c/a, 1-c/a)."""
    q = math.exp(-math.pi * ratio)
    t2 = 2 * q ** 0.25 * sum(q ** (n * (n + 1)) for n in range(0, 200))
    t3 = 1 + 2 * sum(q ** (n * n) for n in range(1, 200))
    t4 = 1 + 2 * sum((-1) ** n * q ** (n * n) for n in range(1, 200))
    k, kc = (t2 / t3) ** 2, (t4 / t3) ** 2
    return k, kc * kc / (1.0 + k)


def ratio_cylinder(k):
    kc = math.sqrt(1 - k * k)
    return ellipke(kc, k)[0] / ellipke(k, kc)[0]


def self_checks():
    K, E = ellipke(1 / math.sqrt(2))
    assert abs(K - 1.8540746773013719) < 1e-13 and abs(E - 1.3506438810476755) < 1e-13
    for k in (0.1, 0.37, 0.8, 0.95):                # Legendre relation
        K, E = ellipke(k)
        Kp, Ep = ellipke(math.sqrt(1 - k * k))
        assert abs(E * Kp + Ep * K - K * Kp - math.pi / 2) < 1e-12
    for r in (0.2, 1.0, 3.0):                         # theta route vs K'/K
        k, _ = c_over_a_cylinder(r)
        assert abs(ratio_cylinder(k) - r) < 1e-10
    for r in (0.3, 1.0, 3.0):                         # sphere root
        k, _ = c_over_a_sphere(r)
        assert abs(k * ellipke(math.sqrt(1 - k * k), k)[0] / math.atanh(k) - r) < 1e-9


if __name__ == "__main__":
    self_checks()
    ratios = [0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0]
    print("Spence problem, Goodman approximation: c/a versus beta/mu")
    print(" beta/mu |  sphere c/a        1-c/a     |  cylinder c/a      1-c/a")
    for r in ratios:
        ks, ds = c_over_a_sphere(r)
        kc, dc = c_over_a_cylinder(r)
        print(f"  {r:5.2f}  |  {ks:.6f}   {ds:11.4e}   |  {kc:.6f}   {dc:11.4e}")
    print()
    print("Inverse (beta/mu for given c/a):")
    print("  c/a    sphere    cylinder")
    for k in (0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99):
        kc = math.sqrt(1 - k * k)
        print(f"  {k:4.2f}  {ratio_sphere_from_kc(kc):8.5f}  {ratio_cylinder(k):8.5f}")
    print()
    print("Limits: c/a->1 : sphere 1-c/a ~ 2 exp(-pi mu/beta),  cylinder 1-c/a ~ 8 exp(-pi mu/beta)")
    print("        c/a->0 : sphere c/a ~ 4 exp(-beta/mu),        cylinder c/a ~ 4 exp(-pi beta/(2 mu))")
