#!/usr/bin/python3
"""Plot chamber volumes and pressures of a pneuma run against (pseudo) time.

Usage: scripts/plot_chambers.py OUTPUT_DIR [OUTPUT_DIR ...] [-o FILE.png]

Reads OUTPUT_DIR/history.csv (columns c<k>_volume [m^3], c<k>_gas_volume,
c<k>_liquid_volume, c<k>_pressure [Pa]) and draws, like Figure 10 of the source
paper, the gas and liquid volumes of every chamber relative to its initial
volume (top; chambers of very different size share one axis) and the gauge
pressures (bottom). Several directories (e.g. the same scene with gas and
with water in chamber 2) are drawn into one figure. Writes
OUTPUT_DIR/chambers.png unless -o is given.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pneuma_outputs  # noqa: E402


def read(directory):
    rows = pneuma_outputs.history(directory)
    if not rows:
        sys.exit(f"plot_chambers: {directory}/history.csv has no rows")
    return rows


def main(argv):
    out = None
    dirs = []
    args = iter(argv)
    for a in args:
        if a == "-o":
            out = next(args, None)
        else:
            dirs.append(a)
    if not dirs:
        sys.exit(__doc__)
    out = out or f"{dirs[0]}/chambers.png"
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 7))
    for d in dirs:
        rows = read(d)
        t = [r["time"] for r in rows]
        k = 1
        while f"c{k}_volume" in rows[0]:
            def col(name):
                return [r[f"c{k}_{name}"] for r in rows]
            gas, liquid = col("gas_volume"), col("liquid_volume")
            v0 = col("volume")[0]
            if any(gas):
                top.plot(t, [v / v0 for v in gas],
                         label=f"{d}: chamber {k} gas")
            if any(liquid):
                top.plot(t, [v / v0 for v in liquid], "--",
                         label=f"{d}: chamber {k} liquid")
            bottom.plot(t, [p / 1e5 for p in col("pressure")],
                        label=f"{d}: chamber {k}")
            k += 1
        if k == 1:
            sys.exit(f"plot_chambers: {d}/history.csv has no chamber columns")
    top.set_ylabel("volume / initial chamber volume")
    bottom.set_ylabel("gauge gas pressure [bar]")
    bottom.set_xlabel("t (pseudo time; seconds in explicit stages)")
    for ax in (top, bottom):
        ax.grid(True)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"plot_chambers: wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
