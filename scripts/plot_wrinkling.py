#!/usr/bin/python3
"""Plot the load-deflection path of a wrinkling run with beam theory's marks.

Usage: scripts/plot_wrinkling.py OUTPUT_DIR --force F [--monitor K]
       [--wrinkling P_w] [--collapse P_c] [-o FILE.png]

Reads OUTPUT_DIR/history.csv of a run whose force is (t - 1) F after an
inflation stage ending at t = 1 (parameter_files/airbeam_wrinkling.prm)
and draws the force against the downward deflection -m<K>_u_z of monitor
point K (default 1), with the wrinkled fraction of the membrane area on a
second axis. P_w and P_c (the forces at which beam theory's mid-span
moment reaches the wrinkling and the collapse moments) are drawn as
horizontal lines. Unstable states (negative_eigenvalues > 0) are open
dots. The default output is OUTPUT_DIR/wrinkling.png.
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
    options = {"--force": None, "--monitor": "1", "--wrinkling": None,
               "--collapse": None, "-o": None}
    dirs = []
    args = iter(argv)
    for a in args:
        if a in options:
            options[a] = next(args, None)
            if options[a] is None:
                sys.exit(f"plot_wrinkling: {a} needs a value\n" + __doc__)
        else:
            dirs.append(a)
    if len(dirs) != 1 or options["--force"] is None:
        sys.exit(__doc__)
    try:
        force = float(options["--force"])
        marks = {k: float(options[k]) for k in ("--wrinkling", "--collapse")
                 if options[k] is not None}
    except ValueError as e:
        sys.exit(f"plot_wrinkling: {e}")
    rows = pneuma_outputs.history(dirs[0])
    column = f"m{options['--monitor']}_u_z"
    if not rows or column not in rows[0] or "wrinkled_area" not in rows[0]:
        sys.exit(f"plot_wrinkling: {dirs[0]}/history.csv has no rows with "
                 f"the columns {column} and wrinkled_area")
    rows = [r for r in rows if r["time"] >= 1.]
    w = [-r[column] for r in rows]
    P = [(r["time"] - 1.) * force for r in rows]
    area = max(r["wrinkled_area"] + r["slack_area"] for r in rows)
    unstable = [r.get("negative_eigenvalues", 0) > 0 for r in rows]
    fig, ax = plt.subplots(figsize=(7, 5))
    ax.plot(w, P, "-", color="C0")
    ax.plot([a for a, u in zip(w, unstable) if not u],
            [b for b, u in zip(P, unstable) if not u], "o", color="C0",
            ms=3, label="stable state")
    if any(unstable):
        ax.plot([a for a, u in zip(w, unstable) if u],
                [b for b, u in zip(P, unstable) if u], "o", mfc="none",
                color="C3", ms=4, label="unstable state")
    styles = {"--wrinkling": ("C2", "wrinkling load (beam theory)"),
              "--collapse": ("C3", "collapse load (beam theory)")}
    for k, value in marks.items():
        ax.axhline(value, color=styles[k][0], ls=":", label=styles[k][1])
    ax.set_xlabel(f"deflection -u_z of monitor {options['--monitor']} [m]")
    ax.set_ylabel("force P [N]")
    ax2 = ax.twinx()
    total = [r["wrinkled_area"] for r in rows]
    ax2.plot(w, total, "--", color="C1", label="wrinkled area")
    ax2.set_ylabel("wrinkled area [m^2]", color="C1")
    if area > 0 and math.isfinite(area):
        ax2.set_ylim(0, 1.1 * area)
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], loc="lower right")
    ax.grid(True, alpha=0.3)
    out = options["-o"] or os.path.join(dirs[0], "wrinkling.png")
    fig.tight_layout()
    try:
        fig.savefig(out, dpi=120)
    except OSError as e:
        sys.exit(f"plot_wrinkling: cannot write {out}: {e}")
    print(f"plot_wrinkling: wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
