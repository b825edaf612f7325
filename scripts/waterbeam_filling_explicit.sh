#!/bin/bash
# The paper's Figure 10 in the paper's time: the waterbeam of
# parameter_files/waterbeam_filling.prm filled explicitly (central
# differences, the paper's density 1 kg/m^3 as it states, no damping) up to
# t = 0.01 s, as LS-DYNA ran it:
#  - gas:   chamber 1 (halves 1a + 1b) and chamber 2 (here "Chamber 3")
#           inflated to 1 bar, the pressure ramped linearly to t = 0.01 s;
#  - water: the same, with chamber 2 filled with 0.005 m^3 of water (90 % of
#           its volume) "a little bit later", from t = 0.001 s to 0.01 s,
#           its gas held at the same ramped pressure above the water.
# Gravity acts from t = 0. Writes output/waterbeam_filling_explicit/{gas,
# water}/ and the plot chambers.png (scripts/plot_chambers.py: volumes and
# pressures against time), and prints the largest and the final volumes
# next to the quasi-static filling's (scripts/waterbeam_filling.sh, if its
# output is there): the overshoot and the oscillation the dynamics add.
# Extra arguments are passed to pneuma (e.g. --set "Geometry/Mesh file=...").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
# PNEUMA: another build's executable (else the project's, built if needed).
pneuma="${PNEUMA:-$root/build/pneuma}"
[ -n "${PNEUMA:-}" ] || "$root/scripts/build.sh"
cd "$root"
out=output/waterbeam_filling_explicit
mkdir -p "$out"
ramp="1e5*min(t/0.01,1)"
common=(--set "Load stepping/Strategy=explicit"
        --set "Load stepping/Stage end times=0.01"
        --set "Explicit dynamics/Output interval=2e-4"
        --set "Explicit dynamics/Progress interval=10000"
        --set "Loads/Gravity vector/Function expression=0; 0; -9.81"
        --set "Chambers/Chamber 1/Gas/Pressure/Function expression=$ramp"
        --set "Chambers/Chamber 1/Gas/Seal time=0.01"
        --set "Chambers/Chamber 3/Gas/Pressure/Function expression=$ramp")
"$pneuma" parameter_files/waterbeam_filling.prm "${common[@]}" \
  --set "Chambers/Chamber 3/Gas/Seal time=0.01" \
  --set "Output/Directory=$out/gas" "$@" | tee "$out/gas.log" \
  | grep -E "^(stage|  stable|  step|pneuma)"
"$pneuma" parameter_files/waterbeam_filling.prm "${common[@]}" \
  --set "Chambers/Chamber 3/Filling=liquid and gas" \
  --set "Chambers/Chamber 3/Gas/Seal time=-1" \
  --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min(max((t-0.001)/0.009,0),1)" \
  --set "Output/Directory=$out/water" "$@" | tee "$out/water.log" \
  | grep -E "^(stage|  stable|  step|pneuma)"
/usr/bin/python3 "$root/scripts/plot_chambers.py" "$out/gas" "$out/water" -o "$out/chambers.png"
/usr/bin/python3 - "$root/scripts" "$out" output/waterbeam_filling <<'PY'
import os
import sys
sys.path.insert(0, sys.argv[1])
import pneuma_outputs
print("| case | chamber | volume | largest [m^3] | at t [s] | at 0.01 s | quasi-static |")
print("|---|---|---|---|---|---|---|")
for case in ("gas", "water"):
    rows = pneuma_outputs.history(os.path.join(sys.argv[2], case))
    static = os.path.join(sys.argv[3], case)
    srows = (pneuma_outputs.history(static)
             if os.path.exists(os.path.join(static, "history.csv")) else [])
    for c, name in ((1, "1a"), (2, "1b"), (3, "2")):
        kind = "liquid" if c == 3 and case == "water" else "gas"
        key = f"c{c}_{kind}_volume"
        v = [r[key] for r in rows]
        k = max(range(len(v)), key=lambda i: v[i])
        # The quasi-static filling is complete at pseudo time 2.
        s = [r[key] for r in srows if abs(r["time"] - 2.) < 1e-9]
        quasi = f"{s[0]:.6g}" if s else "(not run)"
        print(f"| {case} | {name} | {kind} | {v[k]:.6g} | {rows[k]['time']:.4g}"
              f" | {v[-1]:.6g} | {quasi} |")
PY
echo "written: $out/gas, $out/water, $out/chambers.png"
