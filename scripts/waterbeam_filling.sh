#!/bin/bash
# The paper's Figure 10: gas and liquid volumes of the waterbeam's chambers
# during filling. Runs parameter_files/waterbeam_filling.prm twice:
#  - gas:   chamber 1 (halves 1a + 1b) and chamber 2 inflated to 1 bar and
#           sealed (stage 1, 0 < t <= 1), then held (stage 2, 1 < t <= 2);
#  - water: the same inflation, then chamber 2 is filled with 90 % of its
#           volume of water in stage 2, its gas held at 1 bar above the
#           water (pressure-regulated, as when a waterbeam is pumped up);
#           chamber 1 stays sealed and feels the heavier, larger tube.
# Writes output/waterbeam_filling/{gas,water}/ and the plot
# output/waterbeam_filling/chambers.png (scripts/plot_chambers.py), and
# gas.png, water.png, the filled states, where ParaView is installed.
# Extra arguments are passed to pneuma (e.g. --set "Geometry/Mesh file=...").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/waterbeam_filling
mkdir -p "$out"
common=(--set "Load stepping/Stage end times=1, 2"
        --set "Load stepping/Initial increment=0.125"
        --set "Load stepping/Maximum increment=0.125")
"$root/build/pneuma" parameter_files/waterbeam_filling.prm "${common[@]}" \
  --set "Output/Directory=$out/gas" "$@" | tee "$out/gas.log" | grep -E "^(Step|pneuma)"
"$root/build/pneuma" parameter_files/waterbeam_filling.prm "${common[@]}" \
  --set "Chambers/Chamber 3/Filling=liquid and gas" \
  --set "Chambers/Chamber 3/Gas/Seal time=-1" \
  --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min(max(t-1,0),1)" \
  --set "Output/Directory=$out/water" "$@" | tee "$out/water.log" | grep -E "^(Step|pneuma)"
/usr/bin/python3 "$root/scripts/plot_chambers.py" "$out/gas" "$out/water" -o "$out/chambers.png"
echo "written: $out/gas, $out/water, $out/chambers.png"
source "$root/scripts/scene_tools.sh"
scene_pictures gas water
