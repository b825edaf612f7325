#!/bin/bash
# Path following (solvers/path_following.h) against volume control on the
# neo-Hookean balloon of tests/path_following_sphere (R = 1 m, H = 1 mm,
# mu = 1 MPa, Q2), inflated to the stretch l = 3 past the pressure maximum
# at l = 7^(1/6): by a prescribed volume (which never meets a limit point),
# and by a prescribed pressure, load control to t = 0.1 then arc length
# (cylindrical) to the pole displacement 2 m, with the stability check
# locating the limit point. The same stepping for both (Initial increment
# 0.05, Maximum increment 1). Per mesh: dofs, steps, Newton iterations,
# linear solves, wall time and peak memory (/usr/bin/time), the worst
# deviation of the states from p R/(mu H) = 2 (1/l - 1/l^7), and the error
# of the located limit point in l.
# Usage: benchmarks/stability/path_following.sh   (builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prm="$root/parameter_files/sphere_arc_length.prm"
echo "| refinements | control | dofs | steps | Newton iterations | linear solves | wall s | peak MB | worst path deviation | limit point l error |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for r in 2 3 4; do
  for c in volume arc-length; do
    if [ "$c" = volume ]; then
      set_control=(--set "Chambers/Chamber 1/Gas/Control=volume"
                   --set "Chambers/Chamber 1/Gas/Volume/Function expression=(1+t)^3"
                   --set "Load stepping/Stage end times=0.1, 2"
                   --set "Load stepping/Control=load"
                   --set "Load stepping/Path following/Target monitor value=")
    else
      set_control=()
    fi
    /usr/bin/time -f "%e %M" -o "$work/time" "$pneuma" "$prm" \
      --set "Geometry/Global refinements=$r" --set "Output/Directory=$work/$c" \
      --set "Output/Quiet=true" --set "Output/Write VTU=false" \
      "${set_control[@]}" > /dev/null
    read -r w k < "$work/time"
    /usr/bin/python3 - "$work/$c" "$r" "$c" "$w" "$((k / 1024))" <<'PY'
import csv, json, math, sys
d, r, c, w, mb = sys.argv[1:]
s = json.load(open(f"{d}/summary.json"))
f = lambda l: 2 * (1 / l - 1 / l**7)
worst = 0.
for row in list(csv.DictReader(open(f"{d}/history.csv")))[1:]:
    l = 1 + float(row["m0_u_z [m]"])
    p = float(row["c1_pressure [Pa]"]) / 1000.
    worst = max(worst, abs(p - f(l)) / f(l))
cp = [p for p in s.get("critical_points", []) if p.get("limit_point") == 1]
lim = f"{(1 + cp[0]['monitor']) / 7**(1/6) - 1:+.1e}" if cp else "-"
print(f"| {r} | {c} | {s['dofs']} | {s['steps']} | {s['newton_iterations']} | "
      f"{s['linear_solves']} | {w} | {mb} | {worst:.1e} | {lim} |")
PY
  done
done
