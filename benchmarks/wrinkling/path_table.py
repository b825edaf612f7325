#!/usr/bin/python3
"""Table of the airbeam wrinkling path: benchmarks/wrinkling/run.sh part 2.

Usage: path_table.py OUTPUT_DIR WALL_SECONDS PEAK_MB
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "scripts"))
import pneuma_outputs  # noqa: E402

F, P_w, P_c = 10000., 3822., 7645.
d, wall, mb = sys.argv[1:4]
rows = [r for r in pneuma_outputs.history(d) if r["time"] > 1.]
taut = [r for r in rows if r["plain_minor_force"] >= 0.]
wrinkled = [r for r in rows if r["plain_minor_force"] < 0.]


def stats(rs):
    if not rs:
        return "-", "-", "-"
    its = [r["newton_iterations"] for r in rs]
    # wall_seconds is the run's clock at the step: its increments.
    every = pneuma_outputs.history(d)
    index = {r["step"]: k for k, r in enumerate(every)}
    wall = sum(r["wall_seconds"] - every[index[r["step"]] - 1]["wall_seconds"]
               for r in rs)
    return (f"{sum(its) / len(its):.1f}", f"{max(its):.0f}",
            f"{wall / sum(its):.3f}")


# The first wrinkled point: between the last taut and the first wrinkled
# state of the stage.
onset = "-"
states = [r for r in pneuma_outputs.history(d) if r["time"] >= 1.]
for k in range(1, len(states)):
    if states[k]["plain_minor_force"] < 0.:
        onset = (f"{(states[k - 1]['time'] - 1.) * F:.0f} - "
                 f"{(states[k]['time'] - 1.) * F:.0f}")
        break
peak = max(rows, key=lambda r: r["time"])
unstable = [r for r in rows if r.get("negative_eigenvalues", 0) > 0]
print("| quantity | value |")
print("|---|---|")
print(f"| wall time, peak memory | {wall} s, {mb} MB |")
print(f"| steps in stage 2 (taut / wrinkled) | {len(taut)} / {len(wrinkled)} |")
print(f"| Newton iterations per step, taut: mean / max / wall s per iteration | {' / '.join(stats(taut))} |")
print(f"| Newton iterations per step, wrinkled: mean / max / wall s per iteration | {' / '.join(stats(wrinkled))} |")
print(f"| first wrinkled point between (beam theory's P_w = {P_w:.0f} N is for the mid-span section) | {onset} N |")
print(f"| largest force (beam theory P_c = {P_c:.0f} N) | {(peak['time'] - 1.) * F:.0f} N "
      f"({(peak['time'] - 1.) * F / P_c:.3f} P_c) at a deflection of {-peak['m1_u_z']:.4f} m |")
if unstable:
    print(f"| first unstable state | deflection {-unstable[0]['m1_u_z']:.4f} m, "
          f"force {(unstable[0]['time'] - 1.) * F:.0f} N |")
last = pneuma_outputs.history(d)[-1]
print(f"| at the end (deflection {-last['m1_u_z']:.3f} m) | force "
      f"{(last['time'] - 1.) * F:.0f} N, wrinkled {last['wrinkled_area']:.3f} m^2, "
      f"slack {last['slack_area']:.3f} m^2 |")
