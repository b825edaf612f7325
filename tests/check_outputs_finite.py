#!/usr/bin/python3
"""Every output of a run is finite and well formed.

Usage: check_outputs_finite.py OUTPUT_DIR

Reads every .vtu in OUTPUT_DIR with VTK's XML reader (Debian's
python3-vtk9) and checks every point and cell array for NaN and inf;
checks that summary.json is valid JSON with no non-finite number, and that
history.csv has no nan/inf entry. Prints one line per file and exits 1 if
anything is not finite or cannot be read.
"""
import glob
import json
import math
import sys

import vtk


def check_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid is None or grid.GetNumberOfPoints() == 0:
        return [f"{path}: no points read"]
    bad = []
    for kind, data in (("point", grid.GetPointData()),
                       ("cell", grid.GetCellData())):
        for a in range(data.GetNumberOfArrays()):
            array = data.GetArray(a)
            if array is None:
                continue
            n = array.GetNumberOfTuples() * array.GetNumberOfComponents()
            count = sum(1 for i in range(n)
                        if not math.isfinite(array.GetValue(i)))
            if count:
                bad.append(f"{path}: {kind} field {array.GetName()}: "
                           f"{count} non-finite values")
    points = grid.GetPoints().GetData()
    for i in range(points.GetNumberOfTuples() * 3):
        if not math.isfinite(points.GetValue(i)):
            bad.append(f"{path}: non-finite point coordinates")
            break
    return bad


def walk(value):
    if isinstance(value, dict):
        for v in value.values():
            yield from walk(v)
    elif isinstance(value, list):
        for v in value:
            yield from walk(v)
    else:
        yield value


def main(directory):
    problems, files = [], 0
    for path in sorted(glob.glob(f"{directory}/**/*.vtu", recursive=True)):
        problems += check_vtu(path)
        files += 1
    try:
        summary = json.load(open(f"{directory}/summary.json"),
                            parse_constant=lambda c: float("nan"))
        if any(isinstance(v, float) and not math.isfinite(v)
               for v in walk(summary)):
            problems.append(f"{directory}/summary.json: non-finite number")
        files += 1
    except (OSError, ValueError) as e:
        problems.append(f"{directory}/summary.json: {e}")
    try:
        for line in open(f"{directory}/history.csv").read().split("\n")[1:]:
            for v in line.split(","):
                if v and not math.isfinite(float(v)):
                    problems.append(f"{directory}/history.csv: {v}")
        files += 1
    except (OSError, ValueError) as e:
        problems.append(f"{directory}/history.csv: {e}")
    for p in problems:
        print("FAIL", p)
    if not problems:
        print(f"{files} files of {directory}: every value finite")
    return 1 if problems or files < 3 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
