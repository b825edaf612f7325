#!/bin/bash
# A waterbeam lying on the ground as a flood barrier
# (parameter_files/waterbeam_ground.prm): inflated to 1 bar gauge on the
# ground by dynamic relaxation, chamber 1 filled with 0.25 m^3 of water,
# then a flood rising on one side to 0.4 m. Writes output/waterbeam_ground/
# barrier/, ground.csv and ground.png (scripts/plot_ground.py: the anchors'
# and the ground's forces against the flood's height with their closed
# forms, and the barrier's motion), and barrier.png, the last state, where
# ParaView is installed. Extra arguments are passed to the run (e.g.
# --set "Geometry/Global refinements=1" for the next finer mesh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/waterbeam_ground
mkdir -p "$out"
source "$root/scripts/scene_tools.sh"
scene_run barrier parameter_files/waterbeam_ground.prm "$@"
# The flood's height H and its start (the end of the filling stage), read
# from the parameter file so that the two cannot drift apart.
H=$(grep -o 'H=[0-9.e+-]*' parameter_files/waterbeam_ground.prm | head -n 1 | cut -d= -f2)
start=$(awk -F'[=,]' '$1 ~ /set Stage end times/ { print $3 + 0; exit }' \
  parameter_files/waterbeam_ground.prm)
/usr/bin/python3 "$root/scripts/plot_ground.py" "$out/barrier" \
  --height "$H" --start "$start" --out "$out/ground"
scene_pictures barrier
