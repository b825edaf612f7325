#!/usr/bin/env python3
"""Reference of tests/annulus_torsion: a flat annular membrane a <= r <= b
with a uniform isotropic prestress n0 [N/m], the outer edge fixed and the
inner edge (a rigid hub) turned by theta (Mikulas 1964; Miller & Hedgepeth
1982). Small-strain tension field theory, derived in doc/verification.md
"Annulus under torsion":

  equilibrium: N_rt = K / r^2 everywhere (torque T = 2 pi K);
  wrinkled zone a <= r <= r_w: uniaxial tension N1 along straight rays at
    the angle phi to the radius, sin(phi) = c / r, N1 = K / (c sqrt(r^2 -
    c^2)); the strain along the ray is (N1 - (1 - nu) n0) / EH and the
    shear strain of the ray frame is zero (isotropic law), two ODEs for
    u_r and the rotation omega = u_t / r from the hub (u_r = 0, omega =
    theta);
  taut zone r_w <= r <= b: Lame N_r = A + B/r^2, N_t = A - B/r^2 with
    u_r(b) = 0, omega(b) = 0;
  at r_w all stresses are continuous (the taut side has N2 = 0) and u_r,
    omega are continuous.

For each load K = k n0 a^2 (k > 1: wrinkling starts at k = 1) it solves for
c and r_w, integrates theta, checks that the zones are admissible (taut:
N2 > 0; wrinkled: the membrane over-contracts across the rays), and prints
theta, the torque, c, r_w, and the ray angle and N1 at the probe radii of
the test. Needs mpmath; not run by the tests.
"""
from mpmath import mp, mpf, sqrt, findroot, odefun, asin, pi, degrees

mp.dps = 20
a, b = mpf('0.1'), mpf('0.5')
E, nu, H = mpf('1e9'), mpf('0.3'), mpf('1e-3')
n0 = mpf('10')
EH = E * H
GH = EH / (2 * (1 + nu))


def ray_strain(K, c, r):
    """Strain along the ray of the uniaxial tension N1 on the prestress."""
    return (K / (c * sqrt(r * r - c * c)) - n0 * (1 - nu)) / EH


def wrinkled_zone(K, c):
    """(u_r, omega - theta) from the hub outwards as a function of r."""
    def rhs(r, y):
        u, _ = y
        p = c * c / (r * r)
        q = 1 - p
        en = ray_strain(K, c, r)
        # eps_n = q u' + p u/r + gamma s co, eps_nt = 0 eliminated:
        # q u' - p u/r = (q - p) eps_n.
        du = ((q - p) * en + p * u / r) / q
        gamma = (en - q * du - p * u / r) / ((c / r) * sqrt(q))
        return [du, gamma / r]
    return odefun(rhs, a, [mpf(0), mpf(0)])


def lame(K, c, rw):
    """A, B of the taut zone from the stresses at r_w."""
    Nr = K * sqrt(rw**2 - c**2) / (c * rw**2)
    Nt = K * c / (rw**2 * sqrt(rw**2 - c**2))
    return (Nr + Nt) / 2, rw**2 * (Nr - Nt) / 2


def taut_ur(A, B, r):
    return ((1 - nu) * (A - n0) * r - (1 + nu) * B / r) / EH


def solve(k):
    K = k * n0 * a * a

    def equations(c, rw):
        A, B = lame(K, c, rw)
        u, _ = wrinkled_zone(K, c)(rw)
        return taut_ur(A, B, b), u - taut_ur(A, B, rw)

    c, rw = findroot(equations, (a / 2, sqrt(K / n0)))
    f = wrinkled_zone(K, c)
    # omega(r_w) from the taut side (omega(b) = 0), the hub's by the ODE.
    theta = K / (2 * GH) * (1 / b**2 - 1 / rw**2) - f(rw)[1]
    # Admissible: taut beyond r_w, over-contracted inside.
    A, B = lame(K, c, rw)
    for i in range(1, 41):
        r = rw + (b - rw) * i / 40
        Nr, Nt, Nrt = A + B / r**2, A - B / r**2, K / r**2
        N2 = (Nr + Nt) / 2 - sqrt(((Nr - Nt) / 2) ** 2 + Nrt**2)
        assert N2 > 0, ("taut zone has N2 <= 0 at", r)
    for i in range(1, 40):
        r = a + (rw - a) * i / 40
        u, _ = f(r)
        s, co = c / r, sqrt(1 - c * c / (r * r))
        p, q = s * s, co * co
        en = ray_strain(K, c, r)
        du = ((q - p) * en + p * u / r) / q
        gamma = (en - q * du - p * u / r) / (s * co)
        et = du * p + u / r * q - gamma * s * co
        natural = (-nu * K / (c * sqrt(r * r - c * c)) - n0 * (1 - nu)) / EH
        assert et <= natural, ("wrinkled zone not over-contracted at", r)
    return K, c, rw, theta


if __name__ == '__main__':
    print("onset: K = n0 a^2 =", n0 * a * a, "theta =",
          n0 * a * a / (2 * GH) * (1 / a**2 - 1 / b**2))
    for k in (3, 6):
        K, c, rw, theta = solve(mpf(k))
        print(f"k = {k}: hub rotation theta = {mp.nstr(theta, 15)} rad, "
              f"torque 2 pi K = {mp.nstr(2 * pi * K, 12)} N m, "
              f"c = {mp.nstr(c, 12)} m, r_w = {mp.nstr(rw, 12)} m")
        for r in (0.12, 0.15, 0.2):
            r = mpf(r)
            if r < rw:
                print(f"   r = {mp.nstr(r, 3)}: ray angle "
                      f"{mp.nstr(degrees(asin(c / r)), 10)} deg, N1 = "
                      f"{mp.nstr(K / (c * sqrt(r * r - c * c)), 10)} N/m")
