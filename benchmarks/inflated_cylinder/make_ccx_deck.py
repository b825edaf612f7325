#!/usr/bin/env python3
"""CalculiX (ccx 2.20) reference model of a closed, pressurised thin cylinder.

Problem (same as pneuma's "closed cylinder" geometry)
------------------------------------------------------
  hull      : radius R = 0.23 m, length L = 2 m along x (x = 0 .. 2),
              wall t = 1 mm
  end caps  : flat discs at x = 0 and x = L, same material, thickness 10 mm
              (stiff end plates; they only close the volume)
  material  : E = 7.6e9 Pa, nu = 0.3; with NLGEOM ccx's *ELASTIC is a
              St. Venant-Kirchhoff material (Green strain / PK2 stress)
  load      : internal pressure p = 1e5 Pa (1 bar), follower load
  elements  : S4 shells (ccx expands them internally into 3D bricks)
  supports  : statically determinate (6 constraints, the load is
              self-equilibrated, so the reactions must come out ~0):
                left-cap centre  (0,0,0)   u_x = u_y = u_z = 0
                right-cap centre (L,0,0)   u_y = u_z = 0
                left-cap node on the +z axis next to the rim: u_y = 0
                (stops the rotation about x)

Quantity of interest
--------------------
  dR = radial displacement at mid-length, averaged over the hull node ring
  at x = L/2 (n_axial is chosen even, so that ring lies exactly at x = 1).

References (far from the caps, the hull state is homogeneous)
-------------------------------------------------------------
  linear thin-shell theory with closed ends (hoop pR/t, axial pR/(2t)):
      dR = p R^2 / (E t) * (1 - nu/2)                    = 0.5916447 mm
  exact homogeneous finite-strain SVK membrane, follower pressure:
      solve  t*S_theta = p R lam_x,  t*S_x = p R lam_theta^2 / (2 lam_x)
      with S from plane-stress SVK on the Green strains,
      dR = R (lam_theta - 1)                             = 0.5908384 mm
  Both are recomputed by reference_values() below.

Mesh
----
  hull : n_circ x n_axial structured quads, n_axial = even number closest to
         L n_circ / (2 pi R) (near-square cells);
  caps : O-grid per disc: an m x m square core (m = n_circ/4, half-side
         s = 0.5 R) and n_ring quad layers blended from the square to the
         circle; rim nodes are the hull's end rings (conforming).
  n_circ must be a multiple of 8 (so the cap centre and the node at
  angle 0 are mesh nodes).  All element normals point out of the volume
  (checked by Mesh.check_normals); ccx's shell pressure "P" with a
  POSITIVE value then acts along the outward normal, i.e. it is an
  internal pressure.  Verified with ccx 2.20: a linear run (no NLGEOM)
  gives dR > 0 for +P and exactly -dR for -P; with NLGEOM, -P (external
  pressure, ~100x the buckling pressure of this shell) does not converge.

Usage
-----
  make_ccx_deck.py deck  --target-elements 2000 --job cyl --dir /tmp/x
  make_ccx_deck.py deck  --n-circ 32 --job cyl --dir /tmp/x
  make_ccx_deck.py parse --dat /tmp/x/cyl.dat --meta /tmp/x/cyl.meta.json
                         [--stdout /tmp/x/ccx.log]
  make_ccx_deck.py ref
'deck' writes JOB.inp and JOB.meta.json (mesh facts, ring nodes);
'parse' prints one JSON line with dR [mm], errors, reactions and (from the
ccx log, if given) the Newton iterations and number of equations.
Python 3 standard library only.
"""

import argparse
import os
import json
import math
import re
import sys

# ---------------------------------------------------------------- problem
R = 0.23          # hull radius [m]
L = 2.0           # length [m]
T_HULL = 1.0e-3   # hull wall thickness [m]
T_CAP = 10.0e-3   # end-cap thickness [m]
E = 7.6e9         # Young's modulus [Pa]
NU = 0.3          # Poisson's ratio
P = 1.0e5         # internal pressure [Pa]
# ccx 2.20, S4 shells: a positive "P" acts along the element normal.  The
# normals here point outward, so +P is the internal pressure (verified:
# +P inflates the cylinder, see the docstring).
PRESSURE_SIGN = +1.0
S_CORE = 0.5 * R  # half-side of the square core of the cap O-grid [m]


def reference_values():
    """Return (dR_linear, dR_svk) in metres (see module docstring)."""
    d_lin = P * R * R / (E * T_HULL) * (1.0 - NU / 2.0)
    c = E * T_HULL / (1.0 - NU * NU)  # plane-stress membrane stiffness

    def residual(lt, lx):
        et, ex = 0.5 * (lt * lt - 1.0), 0.5 * (lx * lx - 1.0)
        st, sx = c * (et + NU * ex), c * (ex + NU * et)  # t * PK2
        return (st - P * R * lx, sx - P * R * lt * lt / (2.0 * lx))

    lt, lx = 1.0, 1.0
    for _ in range(50):  # Newton with a finite-difference Jacobian
        f0, f1 = residual(lt, lx)
        h = 1e-8
        a0, a1 = residual(lt + h, lx)
        b0, b1 = residual(lt, lx + h)
        j00, j10 = (a0 - f0) / h, (a1 - f1) / h
        j01, j11 = (b0 - f0) / h, (b1 - f1) / h
        det = j00 * j11 - j01 * j10
        dlt = (f0 * j11 - f1 * j01) / det
        dlx = (j00 * f1 - j10 * f0) / det
        lt, lx = lt - dlt, lx - dlx
        if abs(dlt) + abs(dlx) < 1e-15:
            break
    return d_lin, R * (lt - 1.0)


# ------------------------------------------------------------------- mesh
def n_axial_for(n_circ):
    """Even number of axial cells giving near-square hull cells."""
    return max(2, 2 * round(L * n_circ / (2.0 * math.pi * R) / 2.0))


def n_ring_for(n_circ):
    """Radial quad layers between the cap's square core and its rim."""
    m = n_circ // 4
    h_core = 2.0 * S_CORE / m            # core cell size
    h_rim = 2.0 * math.pi * R / n_circ   # rim cell size
    return max(1, round((R - S_CORE) / (0.5 * (h_core + h_rim))))


def element_count(n_circ):
    m = n_circ // 4
    return n_circ * n_axial_for(n_circ) + 2 * (m * m + n_ring_for(n_circ) * n_circ)


def n_circ_for_target(target):
    """Multiple of 8 whose total element count is closest to target."""
    best = min(range(8, 2001, 8), key=lambda n: abs(element_count(n) - target))
    return best


class Mesh:
    def __init__(self, n_circ):
        if n_circ % 8 != 0 or n_circ < 8:
            sys.exit("n_circ must be a positive multiple of 8")
        self.n_circ = n = n_circ
        self.n_axial = na = n_axial_for(n)
        self.n_ring = n_ring_for(n)
        self.nodes = []      # (x, y, z), node id = index + 1
        self.hull, self.cap_left, self.cap_right = [], [], []

        def add(x, y, z):
            self.nodes.append((x, y, z))
            return len(self.nodes)

        theta = [2.0 * math.pi * i / n for i in range(n)]
        # hull node rings j = 0..na at x_j; ring[j][i] at angle theta_i
        self.ring = []
        for j in range(na + 1):
            x = L * j / na
            self.ring.append([add(x, R * math.cos(th), R * math.sin(th))
                              for th in theta])
        # hull quads: (theta, then x) -> normal e_theta x e_x = +e_r (outward)
        for j in range(na):
            for i in range(n):
                i1 = (i + 1) % n
                self.hull.append((self.ring[j][i], self.ring[j][i1],
                                  self.ring[j + 1][i1], self.ring[j + 1][i]))
        self.mid_ring = self.ring[na // 2]          # x = L/2 exactly
        self.centre = {}
        self.cap_left = self._cap(0.0, self.ring[0], flip=True, add=add,
                                  key="left")
        self.cap_right = self._cap(L, self.ring[na], flip=False, add=add,
                                   key="right")

    def _cap(self, x, rim, flip, add, key):
        """O-grid disc in the (y, z) plane at abscissa x; returns quads.

        Quads are counter-clockwise in (y, z), i.e. normal +x; flip=True
        reverses them (normal -x) for the cap at x = 0.
        """
        n, m, k = self.n_circ, self.n_circ // 4, self.n_ring
        s = S_CORE
        grid = [[add(x, -s + 2 * s * a / m, -s + 2 * s * b / m)
                 for b in range(m + 1)] for a in range(m + 1)]
        self.centre[key] = grid[m // 2][m // 2]
        # node 'kk' on the square's boundary, matched with rim angle
        # 2 pi kk / n (kk = 0 is (s, 0); corners at 45, 135, ... degrees)
        perim = []
        for kk in range(n):
            pos = kk + m // 2
            side, q = (pos // m) % 4, pos % m
            a, b = [(m, q), (m - q, m), (0, m - q), (q, 0)][side]
            perim.append(grid[a][b])
        # ring layers l = 0 (square boundary) .. k (rim = hull ring)
        layers = [perim]
        for l in range(1, k):
            f = l / k
            row = []
            for kk in range(n):
                _, ys, zs = self.nodes[perim[kk] - 1]
                _, yr, zr = self.nodes[rim[kk] - 1]
                row.append(add(x, (1 - f) * ys + f * yr, (1 - f) * zs + f * zr))
            layers.append(row)
        layers.append(list(rim))
        quads = []
        for a in range(m):
            for b in range(m):
                quads.append((grid[a][b], grid[a + 1][b],
                              grid[a + 1][b + 1], grid[a][b + 1]))
        for l in range(k):
            for kk in range(n):
                k1 = (kk + 1) % n
                quads.append((layers[l][kk], layers[l + 1][kk],
                              layers[l + 1][k1], layers[l][k1]))
        if flip:
            quads = [(q[0], q[3], q[2], q[1]) for q in quads]
        return quads

    def check_normals(self):
        """Every element normal must point away from the axis/centre."""
        cx = 0.5 * L
        for quads in (self.hull, self.cap_left, self.cap_right):
            for q in quads:
                p = [self.nodes[i - 1] for i in q]
                u = [p[2][c] - p[0][c] for c in range(3)]
                v = [p[3][c] - p[1][c] for c in range(3)]
                nrm = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0])
                ctr = [sum(pp[c] for pp in p) / 4 for c in range(3)]
                out = (ctr[0] - cx, ctr[1], ctr[2])
                if quads is self.hull:
                    out = (0.0, ctr[1], ctr[2])
                if sum(nrm[c] * out[c] for c in range(3)) <= 0.0:
                    sys.exit("inward element normal found: mesh bug")

    def rotation_stop_node(self):
        """Left-cap node on the +z axis (y = 0), farthest from the centre."""
        best = None
        for q in self.cap_left:
            for i in q:
                x, y, z = self.nodes[i - 1]
                if abs(y) < 1e-12 and z > 0 and (best is None or
                                                  z > self.nodes[best - 1][2]):
                    if i not in self.ring[0]:
                        best = i
        return best


def write_deck(mesh, path, frd):
    def ids(lst, per_line=10):
        return "\n".join(", ".join(str(i) for i in lst[k:k + per_line])
                         for k in range(0, len(lst), per_line))

    rot = mesh.rotation_stop_node()
    out = []
    w = out.append
    w("** closed thin cylinder under internal pressure, generated by "
      "make_ccx_deck.py")
    w("** n_circ=%d n_axial=%d n_ring=%d elements=%d nodes=%d" % (
        mesh.n_circ, mesh.n_axial, mesh.n_ring,
        len(mesh.hull) + len(mesh.cap_left) + len(mesh.cap_right),
        len(mesh.nodes)))
    w("*HEADING")
    w("inflated closed cylinder R=%g L=%g t=%g p=%g" % (R, L, T_HULL, P))
    w("*NODE, NSET=NALL")
    for i, (x, y, z) in enumerate(mesh.nodes, 1):
        w("%d, %.12e, %.12e, %.12e" % (i, x, y, z))
    eid = 0
    for name, quads in (("HULL", mesh.hull), ("CAPL", mesh.cap_left),
                        ("CAPR", mesh.cap_right)):
        w("*ELEMENT, TYPE=S4, ELSET=%s" % name)
        for q in quads:
            eid += 1
            w("%d, %d, %d, %d, %d" % ((eid,) + tuple(q)))
    w("*ELSET, ELSET=EALL")
    w("HULL, CAPL, CAPR")
    w("*NSET, NSET=RING")
    w(ids(mesh.mid_ring))
    w("*NSET, NSET=SUPL")
    w("%d" % mesh.centre["left"])
    w("*NSET, NSET=SUPR")
    w("%d" % mesh.centre["right"])
    w("*NSET, NSET=SUPROT")
    w("%d" % rot)
    w("*NSET, NSET=SUPALL")
    w("SUPL, SUPR, SUPROT")
    w("*MATERIAL, NAME=MAT")
    w("*ELASTIC")
    w("%.6e, %g" % (E, NU))
    w("*SHELL SECTION, ELSET=HULL, MATERIAL=MAT")
    w("%g" % T_HULL)
    w("*SHELL SECTION, ELSET=CAPL, MATERIAL=MAT")
    w("%g" % T_CAP)
    w("*SHELL SECTION, ELSET=CAPR, MATERIAL=MAT")
    w("%g" % T_CAP)
    w("** statically determinate supports (6 constraints)")
    w("*BOUNDARY")
    w("SUPL, 1, 3")
    w("SUPR, 2, 3")
    w("SUPROT, 2, 2")
    w("*STEP, NLGEOM, INC=100")
    w("*STATIC")
    w("1.0, 1.0")
    w("** internal pressure: normals point outward and a positive shell")
    w("** pressure P acts along the normal (verified: the cylinder inflates)")
    w("*DLOAD")
    w("EALL, P, %.6e" % (PRESSURE_SIGN * P))
    w("*NODE PRINT, NSET=RING")
    w("U")
    w("*NODE PRINT, NSET=SUPALL")
    w("RF")
    if frd:
        w("*NODE FILE")
        w("U")
    w("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return rot


# ---------------------------------------------------------------- parsing
def parse_dat(dat_path):
    """Last 'displacements' block of set RING and last 'forces' of SUPALL.

    Returns ({node: (ux, uy, uz)}, {node: (fx, fy, fz)}) of the last
    increment written (= the converged end of the step).
    """
    disp, forces = {}, {}
    block = None
    with open(dat_path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            low = s.lower()
            if low.startswith("displacements") and "set ring" in low:
                block, disp = "u", {}
                continue
            if low.startswith("forces") and "set supall" in low:
                block, forces = "rf", {}
                continue
            if re.match(r"^[a-z]", low):   # any other header
                block = None
                continue
            parts = s.split()
            if block == "u" and len(parts) == 4:
                disp[int(parts[0])] = tuple(float(v) for v in parts[1:])
            elif block == "rf" and len(parts) == 4:
                forces[int(parts[0])] = tuple(float(v) for v in parts[1:])
    return disp, forces


def support_reaction(forces, supports):
    """Largest support reaction [N] in a constrained direction that carries
    no pressure load share (ccx's RF is the internal nodal force, so it
    includes the load at loaded dofs): y and z at the cap centres, y at the
    rotation stop.  The load is self-equilibrated and the supports are
    statically determinate, so this must be ~0."""
    vals = []
    for key, comps in (("left_centre", (1, 2)), ("right_centre", (1, 2)),
                       ("rotation_stop", (1,))):
        f = forces.get(supports[key])
        if f is None:
            return None
        vals += [abs(f[c]) for c in comps]
    return max(vals)


def parse_log(log_path):
    """Newton iterations, number of equations and increments from stdout."""
    iters, neq, incs = 0, None, 0
    lines = open(log_path, errors="replace").read().splitlines()
    for k, line in enumerate(lines):
        s = line.strip().lower()
        if re.match(r"^iteration \d+$", s):
            iters += 1
        elif s.startswith("increment") and "attempt" in s:
            incs += 1
        elif s == "number of equations" and k + 1 < len(lines):
            try:
                neq = int(lines[k + 1].split()[0])
            except (ValueError, IndexError):
                pass
    return iters, neq, incs


def cmd_parse(args):
    meta = json.load(open(args.meta))
    disp, forces = parse_dat(args.dat)
    coords = {int(k): v for k, v in meta["ring_coords"].items()}
    missing = [i for i in coords if i not in disp]
    if missing:
        sys.exit("ring nodes missing in %s (%d of %d)" % (
            args.dat, len(missing), len(coords)))
    dr = []
    for i, (x, y, z) in coords.items():
        ux, uy, uz = disp[i]
        dr.append((uy * y + uz * z) / math.hypot(y, z))
    d_mean = sum(dr) / len(dr)
    d_lin, d_svk = reference_values()
    res = {
        "solver": "calculix",
        "n_circ": meta["n_circ"],
        "n_axial": meta["n_axial"],
        "elements": meta["elements"],
        "nodes": meta["nodes"],
        "dR_mm": d_mean * 1e3,
        "dR_min_mm": min(dr) * 1e3,
        "dR_max_mm": max(dr) * 1e3,
        "err_linear_pct": 100.0 * (d_mean - d_lin) / d_lin,
        "err_nonlinear_pct": 100.0 * (d_mean - d_svk) / d_svk,
        "support_reaction_max_N": support_reaction(forces, meta["supports"]),
    }
    if args.stdout:
        iters, neq, incs = parse_log(args.stdout)
        res.update(newton_iterations=iters, equations=neq, increments=incs)
    print(json.dumps(res))


def cmd_deck(args):
    n = args.n_circ if args.n_circ else n_circ_for_target(args.target_elements)
    mesh = Mesh(n)
    mesh.check_normals()
    os.makedirs(args.dir, exist_ok=True)
    inp = os.path.join(args.dir, args.job + ".inp")
    rot = write_deck(mesh, inp, args.frd)
    n_el = len(mesh.hull) + len(mesh.cap_left) + len(mesh.cap_right)
    meta = {
        "n_circ": n, "n_axial": mesh.n_axial, "n_ring": mesh.n_ring,
        "elements": n_el, "nodes": len(mesh.nodes),
        "hull_elements": len(mesh.hull),
        "supports": {"left_centre": mesh.centre["left"],
                     "right_centre": mesh.centre["right"],
                     "rotation_stop": rot},
        "ring_x": L * (mesh.n_axial // 2) / mesh.n_axial,
        "ring_coords": {str(i): mesh.nodes[i - 1] for i in mesh.mid_ring},
    }
    with open(os.path.join(args.dir, args.job + ".meta.json"), "w") as f:
        json.dump(meta, f)
    print("wrote %s: n_circ=%d n_axial=%d n_ring=%d elements=%d nodes=%d"
          % (inp, n, mesh.n_axial, mesh.n_ring, n_el, len(mesh.nodes)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    d = sub.add_parser("deck", help="write JOB.inp and JOB.meta.json")
    g = d.add_mutually_exclusive_group(required=True)
    g.add_argument("--n-circ", type=int, help="elements around (multiple of 8)")
    g.add_argument("--target-elements", type=int,
                   help="pick n_circ so the total element count is closest")
    d.add_argument("--job", default="cyl")
    d.add_argument("--dir", default=".")
    d.add_argument("--frd", action="store_true",
                   help="also write U to JOB.frd (*NODE FILE) for viewing")
    p = sub.add_parser("parse", help="dR from JOB.dat")
    p.add_argument("--dat", required=True)
    p.add_argument("--meta", required=True)
    p.add_argument("--stdout", help="ccx stdout log (iterations, equations)")
    sub.add_parser("ref", help="print the reference values")
    args = ap.parse_args()
    if args.cmd == "deck":
        cmd_deck(args)
    elif args.cmd == "parse":
        cmd_parse(args)
    else:
        d_lin, d_svk = reference_values()
        print("dR linear = %.7f mm, dR SVK membrane = %.7f mm"
              % (d_lin * 1e3, d_svk * 1e3))


if __name__ == "__main__":
    main()
