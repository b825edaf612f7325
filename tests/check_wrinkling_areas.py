#!/usr/bin/python3
"""summary.json and the VTU report the same wrinkled and slack areas.

Usage: check_wrinkling_areas.py PNEUMA [RANKS]

Runs Wong & Pellegrino's sheet in shear (tests/shear_sheet.cc, Q1 on a
flat rectangle: wrinkled in the middle, slack corners at the free sides)
with VTU output, on RANKS MPI ranks (1), and sums over the final VTU's
cells the fields wrinkled_fraction and slack_fraction times the cell's
reference area (a flat bilinear quad of the VTU's points, which are the
reference surface's: exactly the area the Gauss rule integrates). Both sums must
equal summary.json's wrinkled_area and slack_area to 1e-5 relative (the
VTU stores 32-bit floats): the areas have one definition, by quadrature
point (postprocess::cell_wrinkling). Prints reference, value and relative
error; exits 1 over the tolerance, if either area is zero (the scene must
have both states), or if the run fails.
"""
import glob
import json
import os
import shutil
import subprocess
import sys

import vtk

SETTINGS = {
    "Geometry/Type": "rectangle",
    "Geometry/rectangle/Length": "0.38",
    "Geometry/rectangle/Width": "0.128",
    "Geometry/Global refinements": "3",
    "Materials/Region 0/Thickness": "25e-6",
    "Materials/Region 0/Wrinkling": "tension field",
    "Materials/Region 0/Wrinkling residual stiffness": "1e-3",
    "Materials/Region 0/Saint Venant-Kirchhoff/Young's modulus": "3.53e9",
    "Materials/Region 0/Saint Venant-Kirchhoff/Poisson's ratio": "0.3",
    "Boundary conditions/Fixed boundaries": "2: xyz",
    "Boundary conditions/Fixed regions": "0: z",
    "Boundary conditions/Prescribed displacement boundaries": "3",
    "Boundary conditions/Prescribed displacement/Function expression":
        "1.28e-4*t; 0; 0",
    "Load stepping/Stage end times": "1",
    "Load stepping/Initial increment": "0.5",
    "Output/Quiet": "true",
    "Output/Write VTU": "true",
    "Output/VTU interval": "0",
}


def cell_areas_and_fractions(path):
    """(reference area, wrinkled fraction, slack fraction) of every cell."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    # deal.II writes cell data at the points of each cell's own patch.
    fields = grid.GetPointData()
    wrinkled = fields.GetArray("wrinkled_fraction")
    slack = fields.GetArray("slack_fraction")
    if wrinkled is None or slack is None:
        sys.exit(f"FAIL {path}: no wrinkled_fraction or slack_fraction field")
    result = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        # The points are the reference surface's (ParaView warps them by
        # the displacement).
        p = [grid.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())]
        # A flat quad's area: half the cross product of its diagonals.
        a = [p[2][j] - p[0][j] for j in range(3)]
        b = [p[3][j] - p[1][j] for j in range(3)]
        cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                 a[0] * b[1] - a[1] * b[0])
        area = 0.5 * sum(v * v for v in cross) ** 0.5
        first = ids.GetId(0)
        result.append((area, wrinkled.GetValue(first), slack.GetValue(first)))
    return result


def main(pneuma, ranks):
    directory = f"wrinkling-areas-{ranks}"
    shutil.rmtree(directory, ignore_errors=True)
    command = [pneuma, os.path.join(os.path.dirname(os.path.abspath(
        __file__)), "bad_input", "valid.prm")]
    for key, value in {**SETTINGS, "Output/Directory": directory}.items():
        command += ["--set", f"{key}={value}"]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        print(f"FAIL the run exited with {run.returncode}: "
              + (run.stdout + run.stderr)[-500:])
        return 1
    summary = json.load(open(f"{directory}/summary.json"))
    last = sorted(glob.glob(f"{directory}/solution_*.pvtu"))[-1]
    cells = []
    for piece in glob.glob(last[:-len(".pvtu")] + ".*.vtu"):
        cells += cell_areas_and_fractions(piece)
    ok = True
    for k, name in ((1, "wrinkled_area"), (2, "slack_area")):
        reference = summary[name]
        value = sum(c[0] * c[k] for c in cells)
        error = (value - reference) / reference if reference else float("inf")
        passed = reference > 0 and abs(error) <= 1e-5
        ok = ok and passed
        print(f"{ranks} rank(s), {len(cells)} cells: {name} [m^2] of "
              f"summary.json vs the VTU's sum of "
              f"{name.replace('area', 'fraction')} x cell area: reference "
              f"{reference:.6e} value {value:.6e} relative error "
              f"{error:.1e} (tolerance 1.0e-05) "
              f"{'PASS' if passed else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 1))
