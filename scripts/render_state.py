"""Render the last state of a pneuma run with ParaView, headless.

Run with pvbatch (Debian package paraview):

    pvbatch scripts/render_state.py OUTPUT_DIRECTORY PICTURE.png \
        [--field wrinkling_state] [--scale 1] [--title TEXT]
        [--cable-radius 0.006]

Reads OUTPUT_DIRECTORY/solution.pvd (the membrane) and, if present,
OUTPUT_DIRECTORY/cables.pvd (cables and beams, drawn as dark tubes of
--cable-radius metres), takes the last time step, warps both by their
displacement times --scale (1: the true deformed shape), colours the
membrane by --field (a point or cell field of the VTU: wrinkling_state,
N1, chamber_pressure, ...; default wrinkling_state where the run has it,
else the displacement's magnitude) and writes a 1600 x 900 picture from
an oblique view. Without a display, run it under xvfb-run (Debian
package xvfb): Debian's pvbatch renders through X.
"""
import argparse
import os
import sys

from paraview import simple as pv


def last_time(reader):
    times = reader.TimestepValues
    try:
        times = [float(x) for x in times]
    except TypeError:
        times = [float(times or 0.0)]
    return times[-1] if times else 0.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory")
    parser.add_argument("picture")
    parser.add_argument("--field", default="")
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--title", default="")
    parser.add_argument("--cable-radius", type=float, default=0.006)
    args = parser.parse_args()

    solution = os.path.join(args.directory, "solution.pvd")
    if not os.path.isfile(solution):
        sys.exit("render_state: no %s (was Output/Write VTU off?)" % solution)
    membrane = pv.PVDReader(FileName=solution)
    t = last_time(membrane)
    view = pv.GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1600, 900]
    view.ViewTime = t
    view.OrientationAxesVisibility = 0

    warped = pv.WarpByVector(Input=membrane)
    warped.Vectors = ["POINTS", "displacement"]
    warped.ScaleFactor = args.scale
    shown = pv.Show(warped, view)
    names = list(membrane.PointData.keys()) + list(membrane.CellData.keys())
    field = args.field or ("wrinkling_state" if "wrinkling_state" in names
                           else "displacement")
    if field not in names:
        sys.exit("render_state: no field '%s' in %s (there are: %s)"
                 % (field, solution, ", ".join(sorted(names))))
    where = "POINTS" if field in membrane.PointData.keys() else "CELLS"
    pv.ColorBy(shown, (where, field))
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    lut = pv.GetColorTransferFunction(field)
    if field == "wrinkling_state":
        # Categories: 0 taut, 1 wrinkled, 2 slack.
        lut.InterpretValuesAsCategories = 1
        lut.Annotations = ["0", "taut", "1", "wrinkled", "2", "slack"]
        lut.IndexedColors = [0.23, 0.30, 0.75, 0.87, 0.87, 0.87,
                             0.71, 0.02, 0.15]
    bar = pv.GetScalarBar(lut, view)
    bar.Title = field
    bar.ComponentTitle = ""

    cables = os.path.join(args.directory, "cables.pvd")
    if os.path.isfile(cables):
        lines = pv.PVDReader(FileName=cables)
        moved = pv.WarpByVector(Input=lines)
        moved.Vectors = ["POINTS", "displacement"]
        moved.ScaleFactor = args.scale
        tube = pv.Tube(Input=pv.ExtractSurface(Input=moved))
        tube.Radius = args.cable_radius
        tube.NumberofSides = 12
        tubes = pv.Show(tube, view)
        tubes.ColorArrayName = [None, ""]
        tubes.DiffuseColor = [0.2, 0.2, 0.2]

    if args.title:
        text = pv.Text(Text=args.title)
        label = pv.Show(text, view)
        label.FontSize = 14
        label.WindowLocation = "Upper Center"

    view.CameraPosition = [3.4, -2.6, 1.6]
    view.CameraFocalPoint = [1.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    pv.ResetCamera(view)
    view.CameraParallelProjection = 0
    pv.Render(view)
    pv.SaveScreenshot(args.picture, view, ImageResolution=[1600, 900])
    print("written: %s (t = %g)" % (args.picture, t))


if __name__ == "__main__":
    main()
