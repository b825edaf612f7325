#!/usr/bin/python3
"""Plot the waterbeam on the ground under a flood (scripts/waterbeam_ground.sh).

Usage: scripts/plot_ground.py OUTPUT_DIR --height H --start T0 [--out BASE]

Reads OUTPUT_DIR/history.csv and draws against the flood's height
h = H (t - T0) above the ground (stage 3 of parameter_files/
waterbeam_ground.prm): the flood's horizontal force (the anchors' and the
ground's friction; the anchors' share apart) and the ground's vertical
force with their closed forms for the undeformed round hull
(doc/scenes.md, "Waterbeam on the ground"), and the barrier's motion (the
bottom line's settlement and sideways slide, the turn of its cross-section
from the top and bottom monitors). Writes BASE.png and BASE.csv (default
OUTPUT_DIR/ground).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pneuma_outputs  # noqa: E402

R, GAMMA, LENGTH = 0.23, 9810.0, 2.0
DRY = math.radians(15.0)  # the hull is wetted from 15 degrees off the bottom


def closed_form(h):
    """Flood force on the round hull per the whole length: (thrust, uplift)."""
    level = h - R  # the water line's height above the axis
    if level <= -R * math.cos(DRY):
        return 0.0, 0.0
    wet = math.acos(-level / R)

    def primitive(phi):
        return level * math.sin(phi) + R * (phi / 2 + math.sin(2 * phi) / 4)

    thrust = GAMMA * LENGTH * (level + R * math.cos(DRY)) ** 2 / 2
    uplift = GAMMA * R * LENGTH * (primitive(wet) - primitive(DRY))
    return thrust, uplift


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory")
    parser.add_argument("--height", type=float, required=True)
    parser.add_argument("--start", type=float, required=True)
    parser.add_argument("--out")
    args = parser.parse_args()
    rows = pneuma_outputs.history(args.directory)
    filled = [r for r in rows if abs(r["time"] - args.start) < 1e-9]
    if not filled:
        sys.exit(f"plot_ground: no state at t = {args.start} in {args.directory}")
    weight = -filled[0]["obstacle1_force_z"]
    flood = [r for r in rows if r["time"] >= args.start - 1e-9]
    h = [args.height * (r["time"] - args.start) for r in flood]
    anchors = [-r["reaction_y"] for r in flood]
    # The flood's horizontal force: the anchors' and the ground's friction.
    thrust = [a + r["obstacle1_force_y"] for a, r in zip(anchors, flood)]
    ground = [-r["obstacle1_force_z"] for r in flood]
    forms = [closed_form(x) for x in h]
    turn = [1e3 * (r["m0_u_y"] - r["m1_u_y"]) / (2 * R) for r in flood]
    base = args.out or os.path.join(args.directory, "ground")
    with open(base + ".csv", "w") as f:
        f.write("flood_height [m],thrust [N],thrust_closed_form [N],"
                "anchors [N],ground_force [N],ground_closed_form [N],"
                "bottom_u_y [m],bottom_u_z [m],turn [mrad]\n")
        for x, r, t, a, g, c, q in zip(h, flood, thrust, anchors, ground,
                                       forms, turn):
            f.write("%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n" % (
                x, t, c[0], a, g, weight - c[1], r["m1_u_y"], r["m1_u_z"],
                q))
    fig, (forces, motion) = plt.subplots(1, 2, figsize=(11, 4.2))
    forces.plot(h, thrust, "o-", label="flood's horizontal force")
    forces.plot(h, anchors, "x", label="... carried by the anchors")
    forces.plot(h, [c[0] for c in forms], "k--", lw=0.8,
                label="closed form (round hull)")
    forces.plot(h, ground, "s-", label="ground's vertical force")
    forces.plot(h, [weight - c[1] for c in forms], "k:", lw=0.8,
                label="weight less the closed-form uplift")
    forces.set_xlabel("flood height h [m]")
    forces.set_ylabel("force [N]")
    forces.legend(fontsize=8)
    forces.grid(alpha=0.3)
    motion.plot(h, [1e3 * r["m1_u_y"] for r in flood], "o-",
                label="bottom line, sideways [mm]")
    motion.plot(h, [1e3 * r["m1_u_z"] for r in flood], "s-",
                label="bottom line, settlement [mm]")
    motion.plot(h, turn, "^-", label="turn of the section [mrad]")
    motion.set_xlabel("flood height h [m]")
    motion.legend(fontsize=8)
    motion.grid(alpha=0.3)
    fig.suptitle("Waterbeam on the ground under a flood (mid-span)")
    fig.tight_layout()
    fig.savefig(base + ".png", dpi=130)
    print(f"written {base}.png and {base}.csv")


if __name__ == "__main__":
    main()
