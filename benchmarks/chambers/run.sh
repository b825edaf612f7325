#!/bin/bash
# Chamber benchmarks (issue "Chambers"): wall time, peak memory, Newton
# iterations and error against the references at three mesh sizes, and the
# cost of the chamber terms relative to a prescribed-pressure run.
#   1. V3 sphere through the limit point by volume control (Q2): error of
#      pR/(mu H) at l = 2 (reference 0.984375);
#   2. V5 tank (Q2): error of the level h (reference 0.61148 m) and of w0
#      (48.28 mm);
#   3. the waterbeam filling (parameter_files/waterbeam_filling.prm, water
#      case of scripts/waterbeam_filling.sh) on Gmsh meshes n = 6, 12, 24:
#      no closed-form reference; the level, chamber 1's volume and the tube's
#      top deflection are compared with the finest mesh (observed order from
#      the three);
#   4. cost: the sphere up to p = 1.2 mu H/R by a chamber with prescribed
#      pressure, by a chamber with prescribed volume (same path) and by a
#      plain follower pressure (Loads/Pressure), at the finest size.
# Usage: benchmarks/chambers/run.sh   (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
cd "$here"
measure() { # name, then pneuma arguments; prints wall s, peak MB
  /usr/bin/time -f "%e %M" -o time.txt "$pneuma" "$@" > /dev/null
  read -r wall kb < time.txt
  echo "$wall $((kb / 1024))"
}
field() { # json-ish summary value
  grep -o "\"$2\": [-0-9.e+]*" "$1/summary.json" | head -1 | awk '{print $NF}'
}
column() { # history.csv value: directory, column name, pseudo time or "last"
  /usr/bin/python3 - "$root/scripts" "$@" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import pneuma_outputs
rows = pneuma_outputs.history(sys.argv[2])
row = rows[-1] if sys.argv[4] == "last" else \
    [r for r in rows if abs(r["time"] - float(sys.argv[4])) < 1e-9][0]
print(row[sys.argv[3]])
PY
}
echo "## V3 sphere, volume control through the limit point (Q2)"
echo "| refinements | cells | dofs | steps | Newton its | wall s | peak MB | pR/(muH) at l=2 | error |"
echo "|---|---|---|---|---|---|---|---|---|"
for r in 2 3 4; do
  read -r wall mb < <(measure sphere.prm --set "Geometry/Global refinements=$r")
  p=$(column out/sphere c1_pressure 1)
  printf "| %s | %s | %s | %s | %s | %s | %s | %.6f | %+.2e |\n" "$r" \
    "$(field out/sphere cells)" "$(field out/sphere dofs)" \
    "$(field out/sphere steps)" "$(field out/sphere newton_iterations)" \
    "$wall" "$mb" "$(awk -v p="$p" 'BEGIN{print p/1000}')" \
    "$(awk -v p="$p" 'BEGIN{print (p/1000-0.984375)/0.984375}')"
done
echo
echo "## V5 tank (Q2)"
echo "| refinements | cells | dofs | Newton its | wall s | peak MB | level h [m] | error | w0 [mm] | error |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for r in 2 3 4; do
  read -r wall mb < <(measure tank.prm --set "Geometry/Global refinements=$r")
  h=$(grep -o '"level": [-0-9.e+]*' out/tank/summary.json | awk '{print $2}')
  w=$(column out/tank m0_u_z last)
  printf "| %s | %s | %s | %s | %s | %s | %.6f | %+.2e | %.3f | %+.2e |\n" "$r" \
    "$(field out/tank cells)" "$(field out/tank dofs)" \
    "$(field out/tank newton_iterations)" "$wall" "$mb" "$h" \
    "$(awk -v h="$h" 'BEGIN{print (h-0.61148)/0.61148}')" \
    "$(awk -v w="$w" 'BEGIN{print -1000*w}')" \
    "$(awk -v w="$w" 'BEGIN{print (-w-0.04828)/0.04828}')"
done
echo
echo "## Waterbeam filling, water case (Q1, Gmsh meshes n = 6, 12, 24)"
echo "| n | cells | dofs | steps | Newton its | its/step | wall s | peak MB | level h [m] | V chamber 1 [m³] | tube top u_z [mm] |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
mkdir -p out
for n in 6 12 24; do
  gmsh -2 -format msh22 -setnumber n "$n" "$root/meshes/waterbeam.geo" \
    -o "out/waterbeam_$n.msh" > /dev/null
  read -r wall mb < <(measure "$root/parameter_files/waterbeam_filling.prm" \
    --set "Geometry/gmsh/Mesh file=out/waterbeam_$n.msh" \
    --set "Load stepping/Stage end times=1, 2" \
    --set "Load stepping/Initial increment=0.125" \
    --set "Load stepping/Maximum increment=0.125" \
    --set "Chambers/Chamber 3/Filling=liquid and gas" \
    --set "Chambers/Chamber 3/Gas/Seal time=-1" \
    --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min(max(t-1,0),1)" \
    --set "Output/Write VTU=false" --set "Output/Directory=out/waterbeam")
  /usr/bin/python3 - "$root/scripts" "$n" "$wall" "$mb" out/waterbeam >> out/waterbeam_rows.txt <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import pneuma_outputs
n, wall, mb, d = sys.argv[2:6]
s = pneuma_outputs.summary(d)
r = pneuma_outputs.history(d)[-1]
print(n, s["cells"], s["dofs"], s["steps"], s["newton_iterations"], wall, mb,
      r["c3_level"], r["c1_volume"], r["m4_u_z"] * 1e3)
PY
done
/usr/bin/python3 - out/waterbeam_rows.txt <<'PY'
import math, sys
rows = [l.split() for l in open(sys.argv[1])]
ref = rows[-1]
for r in rows:
    print(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]} | {int(r[4])/int(r[3]):.1f} | {r[5]} | {r[6]} "
          f"| {float(r[7]):.6f} | {float(r[8]):.6f} | {float(r[9]):.4f} |")
names = ["level h", "V chamber 1", "tube top u_z"]
print()
print("| quantity | n=6 - n=24 | n=12 - n=24 | observed order (h halved twice) |")
print("|---|---|---|---|")
for k, name in zip((7, 8, 9), names):
    a, b, c = (float(r[k]) for r in rows)
    order = math.log(abs((a - b) / (b - c))) / math.log(2) if b != c else float("nan")
    print(f"| {name} | {a - c:+.3e} | {b - c:+.3e} | {order:.2f} |")
PY
rm -f out/waterbeam_rows.txt
echo
echo "## Cost of the chamber terms (sphere, Q2, 4 refinements, to p = 1.2 mu H/R)"
echo "| run | Newton its | wall s | assembly s | linear solve s |"
echo "|---|---|---|---|---|"
common=(--set "Geometry/Global refinements=4" --set "Load stepping/Stage end times=1"
        --set "Load stepping/Initial increment=0.1" --set "Load stepping/Maximum increment=0.1")
# The same sphere without its chamber (an unused Chamber subsection is an
# input error): the Chambers subsection cut out of sphere.prm.
awk '/^subsection Chambers/ {skip = 1} skip && /^end$/ {skip = 0; next} !skip' \
  sphere.prm > out/sphere_no_chamber.prm
cost() { # prm file, then pneuma arguments
  local prm="$1"
  shift
  read -r wall mb < <(measure "$prm" "${common[@]}" "$@")
  printf "| %s | %s | %s | %s | %s |\n" "$label" \
    "$(field out/sphere newton_iterations)" "$wall" \
    "$(field out/sphere assembly)" "$(field out/sphere "linear solve")"
}
label="Loads/Pressure (no chamber)"
cost out/sphere_no_chamber.prm --set "Loads/Pressure/Function expression=1200*t"
label="chamber, prescribed pressure"
cost sphere.prm --set "Chambers/Chamber 1/Gas/Control=pressure" --set "Chambers/Chamber 1/Gas/Pressure/Function expression=1200*t"
label="chamber, prescribed volume"
cost sphere.prm --set "Chambers/Chamber 1/Gas/Volume/Function expression=1+1.0498*t"
rm -f time.txt out/sphere_no_chamber.prm
