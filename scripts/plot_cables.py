#!/usr/bin/env python3
"""Axial force and contact line load along cables, at a run's last output
step (scripts/waterbeam_cables.sh).

Reads DIRECTORY/cables.pvd and the last cables_<k>_NNNN.vtu of each cable k
given (VTK's Python module: Debian python3-vtk9, or python3-paraview),
whose points come in pairs, one pair per element, with the point fields
displacement, axial_force and contact_line_load. Plots both against the
arc length along the deformed cable and writes PREFIX.csv (cable, s_m,
x_m, axial_force_N, contact_line_load_N_per_m) and PREFIX.png.

Usage: plot_cables.py DIRECTORY --out PREFIX --title TITLE CABLE [CABLE ...]
"""
import argparse
import csv
import math
import os
import re
import sys


def last_file(directory, cable):
    """The cable's VTU at the largest time step of cables.pvd."""
    with open(os.path.join(directory, "cables.pvd")) as f:
        files = re.findall(r'file="(cables_%d_\d+\.vtu)"' % cable, f.read())
    if not files:
        sys.exit("plot_cables.py: no output of cable %d in %s/cables.pvd"
                 % (cable, directory))
    return os.path.join(directory, sorted(files)[-1])


def read(path):
    import vtk
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    u = data.GetArray("displacement")
    force = data.GetArray("axial_force")
    load = data.GetArray("contact_line_load")
    rows, s, last = [], 0.0, None
    for i in range(grid.GetNumberOfPoints()):
        X = grid.GetPoint(i)
        x = [X[c] + u.GetComponent(i, c) for c in range(3)]
        if last is not None:
            s += math.dist(last, x)
        last = x
        rows.append((s, x[0], force.GetValue(i),
                     load.GetValue(i) if load is not None else 0.0))
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", required=True)
    parser.add_argument("cables", nargs="+", type=int)
    args = parser.parse_args()
    try:
        import vtk  # noqa: F401
    except ImportError:
        print("plot_cables.py: VTK's Python module is missing (Debian "
              "python3-vtk9 or python3-paraview): no cable plot")
        return
    data = {k: read(last_file(args.directory, k)) for k in args.cables}
    with open(args.out + ".csv", "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["cable", "s_m", "x_m", "axial_force_N",
                      "contact_line_load_N_per_m"])
        for k, rows in data.items():
            for s, x, n, q in rows:
                out.writerow([k, "%.6e" % s, "%.6e" % x, "%.6g" % n,
                              "%.6g" % q])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for k, rows in data.items():
        s = [r[0] for r in rows]
        ax[0].plot(s, [r[2] for r in rows], label="cable %d" % k)
        ax[1].plot(s, [r[3] for r in rows], label="cable %d" % k)
    ax[0].set_ylabel("axial force [N]")
    ax[1].set_ylabel("contact line load [N/m]")
    ax[1].set_xlabel("arc length along the deformed cable [m]")
    for a in ax:
        a.grid(True, alpha=0.3)
        a.legend()
    fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.out + ".png", dpi=150)
    print("written: %s.csv, %s.png" % (args.out, args.out))
    for k, rows in data.items():
        forces = [r[2] for r in rows]
        loads = [r[3] for r in rows]
        touching = sum(1 for q in loads if q > 0.0)
        print("cable %d: length %.4f m, axial force %.1f to %.1f N, contact "
              "line load up to %.0f N/m, %d of %d points in contact"
              % (k, rows[-1][0], min(forces), max(forces), max(loads),
                 touching, len(loads)))


if __name__ == "__main__":
    main()
