#!/bin/bash
# The source paper's Figure 7: load-deflection curves of the airbeam with
# its compression element for the absolute pressures 1, 2, 5, 10, 20 and
# 40 bar (parameter_files/airbeam_figure7.prm: 1 bar = the ambient pressure,
# so the gas is filled to p_abs - 1 bar gauge and sealed; then the line
# load on the compression element at mid-span grows under displacement
# control to 0.15 m or 20 kN).
# The 1 bar case has no gauge pressure: a tension-field wall without
# tension has no stiffness at all (a slack bag), so that run keeps the
# plain law (Wrinkling = none: the wall carries compression like the
# paper's shells, without their bending stiffness) and ends where the
# unpressurized wall gives way under the load.
# Writes output/airbeam_figure7/p<bar>bar/ (history.csv, VTU),
# load_deflection.csv (pressure_bar, F_N, deflection_m, pressure_Pa),
# figure7.png, a summary of each curve, and, where ParaView is installed,
# p<bar>bar.png: the deformed beam coloured by its wrinkling state
# (scripts/render_state.py).
# Extra arguments are passed to every pneuma run (e.g. --set ...).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/airbeam_figure7
mkdir -p "$out"
source "$root/scripts/scene_tools.sh"
for bar in 1 2 5 10 20 40; do
  dir="$out/p${bar}bar"
  args=(--set "Chambers/Chamber 1/Gas/Pressure/Function constants=p0=$((bar - 1))e5"
        --set "Output/Directory=$dir")
  [ "$bar" -eq 1 ] && args+=(--set "Materials/Region 0/Wrinkling=none")
  echo "p = $bar bar (absolute): running"
  code=0
  "$root/build/pneuma" parameter_files/airbeam_figure7.prm "${args[@]}" "$@" \
    > "$dir.log" 2>&1 || code=$?
  tail -n 1 "$dir.log"
  # Exit 2 is a curve that ends where the structure gives way: its last
  # converged state is written and plotted.
  if [ "$code" -ne 0 ] && [ "$code" -ne 2 ]; then
    echo "p = $bar bar failed (exit $code), see $dir.log" >&2
    exit "$code"
  fi
done
/usr/bin/python3 "$root/scripts/plot_figure7.py" "$out" 1 2 5 10 20 40
# Pictures of the deformed beams (wrinkling state; the compression element
# as a tube) where ParaView is installed (scripts/install_dependencies.sh
# --pictures).
scene_pictures p1bar p2bar p5bar p10bar p20bar p40bar
