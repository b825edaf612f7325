#!/usr/bin/env python3
"""Points of a spiral cable wound around the waterbeam's whole cross-section
(meshes/waterbeam.geo: chamber 1 of radius R about the x axis, chamber 2 of
radius r about (x, 0, zc) on top), for Cables/Cable k/polyline/Points.

The cable's axis runs on the convex hull of the two circles, offset by
DELTA (the cable's radius plus a small gap): the hull of the circles of
radii R + DELTA and r + DELTA, i.e. chamber 1's arc, chamber 2's arc over
the top and the two common tangents between them, which the cable spans
freely over the notch where the chambers meet. Node k of n lies at
x = L k / n and at the angle psi = HAND * 2 pi TURNS k / n from +z
(towards +y for HAND = +1), at the hull's distance from the x axis in that
direction: TURNS turns from the top of chamber 2 at x = 0.

Usage: wrap_points.py [--delta 0.0055] [--turns 1] [--elements 160]
                      [--hand 1|-1] [--per-line 4]
Prints the points as "x, y, z; x, y, z; ..." with deal.II's line
continuations ("\\" at the end of a line), PER-LINE points per line.
"""
import argparse
import math

R, r, ZC, L = 0.23, 0.03, 0.26, 2.0


def hull_distance(psi, delta):
    """Distance from the x axis to the offset hull along angle psi (from +z
    towards +y)."""
    ra, rb = R + delta, r + delta
    d = (math.sin(psi), math.cos(psi))  # (y, z)
    best = ra
    # Chamber 2's offset circle: the far intersection of the ray.
    b = d[1] * ZC
    disc = b * b - (ZC * ZC - rb * rb)
    if disc >= 0.0:
        best = max(best, b + math.sqrt(disc))
    # The common tangents: from chamber 1's tangent point to chamber 2's.
    cphi = (ra - rb) / ZC
    sphi = math.sqrt(1.0 - cphi * cphi)
    for s in (1.0, -1.0):
        p = (s * ra * sphi, ra * cphi)
        q = (s * rb * sphi, ZC + rb * cphi)
        e = (q[0] - p[0], q[1] - p[1])
        det = -d[0] * e[1] + d[1] * e[0]
        if abs(det) < 1e-14:
            continue
        t = (-p[0] * e[1] + p[1] * e[0]) / det
        u = (d[0] * p[1] - d[1] * p[0]) / det
        if 0.0 <= u <= 1.0 and t > 0.0:
            best = max(best, t)
    return best


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--delta", type=float, default=0.0055)
    parser.add_argument("--turns", type=float, default=1.0)
    parser.add_argument("--elements", type=int, default=160)
    parser.add_argument("--hand", type=float, default=1.0)
    parser.add_argument("--per-line", type=int, default=4)
    a = parser.parse_args()
    points = []
    for k in range(a.elements + 1):
        psi = a.hand * 2.0 * math.pi * a.turns * k / a.elements
        rho = hull_distance(psi, a.delta)
        points.append("%.6f, %.6f, %.6f" % (L * k / a.elements,
                                            rho * math.sin(psi) + 0.0,
                                            rho * math.cos(psi)))
    lines = ["; ".join(points[i:i + a.per_line])
             for i in range(0, len(points), a.per_line)]
    print(";\\\n      ".join(lines))


if __name__ == "__main__":
    main()
