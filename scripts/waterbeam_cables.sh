#!/bin/bash
# The paper's Figure 11: the waterbeam with two spiral cables around both
# chambers (parameter_files/waterbeam_cables.prm), inflated and sealed at
# 2 bar absolute, chamber 2 filled with 5 litres of water while the cables
# are tensioned, then the transverse force on chamber 2 at mid-span to 3 cm.
# For comparison the same waterbeam without cables (the water variant of
# scripts/waterbeam_bending.sh) runs alongside.
# Writes output/waterbeam_cables/{cables,no_cables}/, bending.csv and
# bending.png (scripts/plot_bending.py: force against deflection, chamber
# pressures and volumes), cable_forces.csv and cable_forces.png (scripts/plot_cables.py:
# axial force and contact line load along both cables at the end), and
# cables.png, the last state, where ParaView is installed. Extra arguments
# are passed to both runs.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/waterbeam_cables
mkdir -p "$out"
source "$root/scripts/scene_tools.sh"
scene_run cables parameter_files/waterbeam_cables.prm "$@"
# The walls smoothed as in the cables scene (its parameter file's value,
# read here so that the two cannot drift apart), so that only the cables
# differ.
zeta=$(awk '$2 == "Wrinkling" && $3 == "smoothing" { print $5; exit }' \
  parameter_files/waterbeam_cables.prm)
smoothing=()
for r in 0 1 2 3; do
  smoothing+=(--set "Materials/Region $r/Wrinkling smoothing=$zeta")
done
scene_run no_cables parameter_files/waterbeam_bending.prm "${waterbeam_water[@]}" \
  "${smoothing[@]}" "$@"
/usr/bin/python3 "$root/scripts/plot_bending.py" --out "$out/bending" \
  --title "Waterbeam, chamber 2 water-filled, with and without the spiral cables" \
  "with the cables:$out/cables:2:4:1" "without cables:$out/no_cables:2:4:1"
/usr/bin/python3 "$root/scripts/plot_cables.py" "$out/cables" --out "$out/cable_forces" \
  --title "Spiral cables of the waterbeam at the end of the loading" 1 2
scene_pictures cables
