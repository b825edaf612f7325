#!/usr/bin/python3
"""Plot the load path of a pneuma run with its stability.

Usage: scripts/plot_path.py OUTPUT_DIR [-x COLUMN] [-y COLUMN] [-o FILE.png]

Reads OUTPUT_DIR/history.csv and draws COLUMN y against COLUMN x. The
defaults are the pressure of chamber 1 (c1_pressure) against the
displacement of monitor point 0 (m0_u_x) when these exist, otherwise the
pseudo time against the monitor's displacement. Stable states
(negative_eigenvalues = 0) are drawn as solid dots joined by solid lines,
unstable states as open dots joined by dashed lines, and the states where
the count changes are marked and labelled with the count. The default
output is OUTPUT_DIR/path.png. A stability column that is missing
(Stability/Check inertia = false) draws the path in one style.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pneuma_outputs  # noqa: E402


def main(argv):
    out, x_name, y_name, dirs = None, None, None, []
    args = iter(argv)
    for a in args:
        if a == "-o":
            out = next(args, None)
        elif a == "-x":
            x_name = next(args, None)
        elif a == "-y":
            y_name = next(args, None)
        else:
            dirs.append(a)
    if len(dirs) != 1:
        sys.exit(__doc__)
    rows = pneuma_outputs.history(dirs[0])
    if not rows:
        sys.exit(f"plot_path: {dirs[0]}/history.csv has no rows")
    columns = rows[0].keys()
    x_name = x_name or ("m0_u_x" if "m0_u_x" in columns else "step")
    y_name = y_name or ("c1_pressure" if "c1_pressure" in columns else "time")
    for name in (x_name, y_name):
        if name not in columns:
            sys.exit(f"plot_path: {dirs[0]}/history.csv has no column "
                     f"'{name}' (columns: {', '.join(columns)})")
    x = [r[x_name] for r in rows]
    y = [r[y_name] for r in rows]
    n = [r.get("negative_eigenvalues", math.nan) for r in rows]
    fig, ax = plt.subplots(figsize=(7, 5))
    for k in range(1, len(rows)):
        unstable = n[k] > 0 or (n[k - 1] > 0 and math.isnan(n[k]))
        ax.plot(x[k - 1:k + 1], y[k - 1:k + 1], "--" if unstable else "-",
                color="C3" if unstable else "C0")
    stable = [k for k in range(len(rows)) if not n[k] > 0]
    unstable = [k for k in range(len(rows)) if n[k] > 0]
    ax.plot([x[k] for k in stable], [y[k] for k in stable], "o", color="C0",
            label="stable")
    ax.plot([x[k] for k in unstable], [y[k] for k in unstable], "o",
            mfc="none", color="C3", label="unstable (negative eigenvalues)")
    for k in range(1, len(rows)):
        if not math.isnan(n[k]) and not math.isnan(n[k - 1]) \
                and n[k] != n[k - 1]:
            ax.annotate(f"{int(n[k - 1])} -> {int(n[k])}", (x[k], y[k]),
                        textcoords="offset points", xytext=(6, 6))
    units = pneuma_outputs.history_units(dirs[0])
    ax.set_xlabel(f"{x_name} [{units.get(x_name, '')}]")
    ax.set_ylabel(f"{y_name} [{units.get(y_name, '')}]")
    ax.legend()
    ax.grid(True, alpha=0.3)
    out = out or f"{dirs[0]}/path.png"
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"plot_path: wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
