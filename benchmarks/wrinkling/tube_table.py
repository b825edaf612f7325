#!/usr/bin/python3
"""The cantilever tube through its limit point: benchmarks/wrinkling/run.sh
part 3. Usage: tube_table.py OUTPUT_DIR WALL_SECONDS
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import pneuma_outputs  # noqa: E402

R, L, p = 0.1, 1., 1e4
M_c = math.pi * p * R ** 3
d, wall = sys.argv[1:3]
rows = [r for r in pneuma_outputs.history(d) if r["time"] > 1.]
P = [(r["time"] - 1.) * M_c / L for r in rows]
M = [f * (L + r["m0_u_x"]) for f, r in zip(P, rows)]
k = max(range(len(rows)), key=lambda i: P[i])
j = max(range(len(rows)), key=lambda i: M[i])
print("| quantity | value |")
print("|---|---|")
print(f"| wall time, steps | {wall} s, {len(rows)} |")
print(f"| largest force | {P[k] / (M_c / L):.4f} P_c at tip deflection "
      f"{-rows[k]['m0_u_z']:.3f} L, tip shortening {-rows[k]['m0_u_x']:.4f} L |")
print(f"| largest root moment P (L + u_x) | {M[j] / M_c:.4f} M_c at tip "
      f"deflection {-rows[j]['m0_u_z']:.3f} L |")
print(f"| last state | tip deflection {-rows[-1]['m0_u_z']:.3f} L, force "
      f"{P[-1] / (M_c / L):.4f} P_c |")
