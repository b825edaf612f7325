#!/usr/bin/env python3
"""Load-deflection curves of beams bent after their inflation, side by side
(scripts/waterbeam_bending.sh, scripts/tensairity_beam.sh).

Each RUN is LABEL:DIRECTORY:T0:LOAD_MONITOR:BOTTOM_MONITOR. The transverse
force F is the change of the supports' vertical reaction since t = T0
(history.csv column reaction_z): the force the mesh carries. The scenes'
load functions say F = (t - T0) 10 kN, but a load band narrower than its
cells is integrated at the cells' quadrature points, and on a coarse mesh
the force applied differs (two thirds of it on the waterbeam's 2640-cell
mesh); the nominal force is printed beside it. The
deflections are the downward displacements since t = T0 of the monitor
point under the load (LOAD_MONITOR) and of the bottom of the tube at
mid-span (BOTTOM_MONITOR), the latter the beam's global bending. Columns
c<k>_pressure and c<k>_volume of each run's history.csv give its chambers'
gauge pressures and volume changes.

Usage: plot_bending.py --out PREFIX --title TITLE RUN [RUN ...]
Writes PREFIX.csv (label, F_N, F_nominal_N, load_deflection_m, bottom_deflection_m,
chamber pressures and volumes), PREFIX.png and prints a summary.
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pneuma_outputs  # noqa: E402

F_PER_T = 1e4  # N per unit of pseudo time in the loading stage


def read(spec):
    label, directory, t0, load, bottom = spec.rsplit(":", 4)
    t0 = float(t0)
    rows = pneuma_outputs.history(directory)
    start = [r for r in rows if abs(r["time"] - t0) < 1e-9]
    if not start:
        print("%s: no state at t = %g (the run ended before the load), "
              "left out" % (label, t0))
        return None
    s = start[0]
    chambers = sorted({k.split("_")[0] for k in s
                       if k.startswith("c") and k.endswith("_pressure")
                       and k.split("_")[0][1:].isdigit()})
    points = []
    for r in rows:
        if r["time"] < t0 - 1e-9:
            continue
        points.append({
            "F": r["reaction_z"] - s["reaction_z"],
            "F_nominal": F_PER_T * (r["time"] - t0),
            "load": -(r["m%s_u_z" % load] - s["m%s_u_z" % load]),
            "bottom": -(r["m%s_u_z" % bottom] - s["m%s_u_z" % bottom]),
            "p": [r[c + "_pressure"] for c in chambers],
            "dV": [r[c + "_volume"] - s[c + "_volume"] for c in chambers],
        })
    return label, chambers, points


def at(points, F, key):
    """The curve's KEY at force F by linear interpolation (NaN outside)."""
    for a, b in zip(points, points[1:]):
        if a["F"] <= F <= b["F"] and b["F"] > a["F"]:
            return a[key] + (F - a["F"]) / (b["F"] - a["F"]) * (b[key] - a[key])
    return math.nan


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", required=True)
    parser.add_argument("runs", nargs="+")
    args = parser.parse_args()
    runs = [r for r in map(read, args.runs) if r is not None]
    if not runs:
        sys.exit("plot_bending.py: no run reached its loading stage")
    with open(args.out + ".csv", "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["label", "F_N", "F_nominal_N", "load_deflection_m",
                      "bottom_deflection_m", "chamber", "pressure_Pa",
                      "volume_change_m3"])
        for label, chambers, points in runs:
            for p in points:
                row = [label, "%.6g" % p["F"], "%.6g" % p["F_nominal"],
                       "%.6e" % p["load"],
                       "%.6e" % p["bottom"]]
                for c, (pc, dv) in enumerate(zip(p["p"], p["dV"])):
                    out.writerow(row + [chambers[c], "%.6g" % pc,
                                        "%.6e" % dv])
                if not chambers:
                    out.writerow(row + ["", "", ""])
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    for label, chambers, points in runs:
        F = [1e-3 * p["F"] for p in points]
        line, = ax[0][0].plot([1e3 * p["bottom"] for p in points], F,
                              marker=".", label=label)
        ax[0][1].plot([1e3 * p["load"] for p in points], F, marker=".",
                      color=line.get_color(), label=label)
        styles = ["-", "--", ":", "-."]
        for c, name in enumerate(chambers):
            ax[1][0].plot(F, [1e-5 * p["p"][c] for p in points],
                          styles[c % 4], color=line.get_color(),
                          label="%s, %s" % (label, name))
            ax[1][1].plot(F, [1e6 * p["dV"][c] for p in points],
                          styles[c % 4], color=line.get_color(),
                          label="%s, %s" % (label, name))
    ax[0][0].set_xlabel("bottom of the tube at mid-span, deflection [mm]")
    ax[0][1].set_xlabel("under the load, deflection [mm]")
    for a in (ax[0][0], ax[0][1]):
        a.set_ylabel("transverse force F (support reaction) [kN]")
    ax[1][0].set_ylabel("chamber gauge pressure [bar]")
    ax[1][1].set_ylabel("chamber volume change [cm^3]")
    for a in (ax[1][0], ax[1][1]):
        a.set_xlabel("transverse force F [kN]")
    for a in ax.flat:
        a.grid(True, alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.out + ".png", dpi=150)
    print("written: %s.csv, %s.png" % (args.out, args.out))
    common = min(points[-1]["F"] for _, _, points in runs)
    for label, chambers, points in runs:
        last = points[-1]
        print("%s: last F = %.2f kN (nominal %.2f kN), %.1f mm under the "
              "load, %.2f mm at the bottom; at F = %.2f kN (reached by every "
              "run) %.2f mm at the bottom; pressures %s bar"
              % (label, 1e-3 * last["F"], 1e-3 * last["F_nominal"],
                 1e3 * last["load"],
                 1e3 * last["bottom"], 1e-3 * common,
                 1e3 * at(points, common, "bottom"),
                 " / ".join("%s %.3f" % (c, 1e-5 * p)
                            for c, p in zip(chambers, last["p"]))))


if __name__ == "__main__":
    main()
