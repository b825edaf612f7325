#!/usr/bin/env python3
"""The source paper's Figure 7 from the runs of scripts/airbeam_figure7.sh:
load-deflection curves of the airbeam with its compression element, one
per absolute pressure. F = (t - 1) 10 kN is the line load on the
compression element (parameter_files/airbeam_figure7.prm); the deflection
is the downward displacement of the top of the tube at mid-span (monitor 0,
under the compression element) since the end of the inflation (t = 1).

Usage: plot_figure7.py OUTPUT_DIRECTORY BAR [BAR ...]
Reads OUTPUT_DIRECTORY/p<BAR>bar/history.csv; writes
OUTPUT_DIRECTORY/load_deflection.csv and OUTPUT_DIRECTORY/figure7.png, and
prints a summary.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pneuma_outputs  # noqa: E402

F_PER_T = 1e4  # N per unit of pseudo time in stage 2


def curve(directory):
    rows = pneuma_outputs.history(directory)
    inflated = [r for r in rows if abs(r["time"] - 1.0) < 1e-9]
    if not inflated:
        return None
    z0 = inflated[0]["m0_u_z"]
    return [(F_PER_T * (r["time"] - 1.0), -(r["m0_u_z"] - z0),
             r["c1_pressure"], r.get("wrinkled_area", float("nan")))
            for r in rows if r["time"] >= 1.0 - 1e-9]


def main():
    out, bars = sys.argv[1], [int(b) for b in sys.argv[2:]]
    curves = {}
    with open(os.path.join(out, "load_deflection.csv"), "w") as f:
        f.write("pressure_bar,F_N,deflection_m,pressure_Pa\n")
        for bar in bars:
            c = curve(os.path.join(out, "p%dbar" % bar))
            if c is None:
                print("p = %d bar: no inflated state, left out" % bar)
                continue
            curves[bar] = c
            for F, w, p, _ in c:
                f.write("%d,%.6g,%.6e,%.6g\n" % (bar, F, w, p))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for bar, c in curves.items():
        ax.plot([1e3 * w for _, w, _, _ in c], [1e-3 * F for F, _, _, _ in c],
                marker=".", label="%d bar" % bar)
    ax.set_xlabel("deflection under the load [mm] (top of the tube, mid-span)")
    ax.set_ylabel("transverse force F [kN]")
    ax.set_title("Airbeam with compression element (paper, Figure 7)\n"
                 "absolute gas pressures; 1 bar = atmospheric")
    ax.grid(True, alpha=0.3)
    ax.legend(title="gas pressure (absolute)")
    fig.tight_layout()
    png = os.path.join(out, "figure7.png")
    fig.savefig(png, dpi=150)
    print("written: %s, %s" % (os.path.join(out, "load_deflection.csv"), png))
    for bar, c in curves.items():
        F, w, p, wr = c[-1]
        stiffness = c[1][0] / c[1][1] if len(c) > 1 and c[1][1] > 0 else 0.
        wrinkled = ("%.3g m^2" % wr) if wr == wr else "- (no wrinkling)"
        print("p = %2d bar: last F = %.2f kN at %.1f mm (initial stiffness "
              "%.3g kN/mm), gauge pressure %.4g bar, wrinkled area %s"
              % (bar, 1e-3 * F, 1e3 * w, 1e-6 * stiffness, 1e-5 * p,
                 wrinkled))


if __name__ == "__main__":
    main()
