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
# as a tube) where ParaView is installed (Debian: paraview, and xvfb
# without a display).
if command -v pvbatch > /dev/null; then
  render=(pvbatch)
  [ -z "${DISPLAY:-}" ] && command -v xvfb-run > /dev/null &&
    render=(xvfb-run -a -s "-screen 0 1920x1080x24" pvbatch)
  for bar in 1 2 5 10 20 40; do
    "${render[@]}" "$root/scripts/render_state.py" "$out/p${bar}bar" \
      "$out/p${bar}bar.png" --title "$bar bar (absolute), last converged state" \
      2>/dev/null | grep written || echo "p = $bar bar: no picture (pvbatch failed)"
  done
else
  echo "pvbatch not found: install paraview (and xvfb) for pictures of the deformed beams"
fi
