#!/bin/bash
# Waterbeam bending (the paper's announced next step, section 5): the
# waterbeam of parameter_files/waterbeam_bending.prm, inflated to 1 bar
# gauge (2 bar absolute) and sealed, then bent by a transverse force F on
# chamber 2 at mid-span, in two variants:
#  - gas:   chamber 2 gas-filled (the file as it is);
#  - water: chamber 2 filled with 5 litres of water (90 % of its volume, as
#           in Figure 10) in stage 2, its gas sealed at the end of the
#           filling;
# and, for comparison, the airbeam tube of parameter_files/airbeam.prm at
# the same support, pressure (sealed gas, 2 bar absolute), wall (tension
# field) and load band (F on the top of the tube at mid-span), to collapse.
# Writes output/waterbeam_bending/{gas,water,airbeam}/ and bending.csv,
# bending.png (scripts/plot_bending.py): force against the deflection of the
# bottom at mid-span (the beam's bending) and under the load, the chambers'
# pressures and volumes; pictures of the last states where ParaView is
# installed. Extra arguments are passed to the waterbeam runs.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/waterbeam_bending
mkdir -p "$out"
source "$root/scripts/scene_tools.sh"
scene_run gas parameter_files/waterbeam_bending.prm "$@"
scene_run water parameter_files/waterbeam_bending.prm "${waterbeam_water[@]}" "$@"
# The airbeam: the main job's tube with the waterbeam's gas, wall and load.
scene_run airbeam parameter_files/airbeam.prm \
  --set "Geometry/Global refinements=3" \
  --set "Materials/Region 0/Wrinkling=tension field" \
  --set "Loads/Pressure/Function expression=0" \
  --set "Chambers/Number of chambers=1" \
  --set "Chambers/Ambient pressure=1e5" \
  --set "Chambers/Chamber 1/Regions=0, 1, 2" \
  --set "Chambers/Chamber 1/Gas/Seal time=1" \
  --set "Chambers/Chamber 1/Gas/Pressure/Function expression=1e5*min(t, 1)" \
  --set "Loads/Surface traction/Function constants=F=10000, b=0.0625, R=0.23" \
  --set "Load stepping/Stage end times=1, 3" \
  --set "Load stepping/Control=load, displacement" \
  --set "Load stepping/Initial increment=0.1" \
  --set "Load stepping/Maximum increment=0.1" \
  --set "Load stepping/Path following/Monitor point=0" \
  --set "Load stepping/Path following/Monitor component=z" \
  --set "Load stepping/Path following/Target monitor value=-0.1" \
  --set "Load stepping/Path following/Maximum steps=300" \
  --set "Stability/Check inertia=true"
# Monitors: waterbeam 4 = top of chamber 2, 1 = bottom of chamber 1;
# airbeam 0 = top, 1 = bottom (all at mid-span).
/usr/bin/python3 "$root/scripts/plot_bending.py" --out "$out/bending" \
  --title "Waterbeam bending (1 bar gauge, 2 bar absolute, sealed) against the airbeam" \
  "waterbeam, chamber 2 gas:$out/gas:2:4:1" \
  "waterbeam, chamber 2 water:$out/water:2:4:1" \
  "airbeam:$out/airbeam:1:0:1"
scene_pictures gas water airbeam
