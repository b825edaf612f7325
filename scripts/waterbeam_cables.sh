#!/bin/bash
# The paper's Figure 11: the waterbeam with two spiral cables around both
# chambers (parameter_files/waterbeam_cables.prm), inflated and sealed at
# 2 bar absolute, chamber 2 filled with 5 litres of water while the cables
# are tensioned, then the transverse force on chamber 2 at mid-span to 3 cm.
# For comparison the same waterbeam without cables (the water variant of
# scripts/waterbeam_bending.sh) runs alongside.
# Writes output/waterbeam_cables/{cables,no_cables}/, bending.csv and
# bending.png (scripts/plot_bending.py: force against deflection, chamber
# pressures and volumes), cables.csv and cables.png (scripts/plot_cables.py:
# axial force and contact line load along both cables at the end), and
# pictures of the last state where ParaView is installed. Extra arguments
# are passed to both runs.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/waterbeam_cables
mkdir -p "$out"
run() { # name, parameter file, arguments...
  local name=$1 file=$2 code=0
  shift 2
  echo "$name: running"
  "$root/build/pneuma" "$file" --set "Output/Directory=$out/$name" "$@" \
    > "$out/$name.log" 2>&1 || code=$?
  tail -n 1 "$out/$name.log"
  if [ "$code" -ne 0 ] && [ "$code" -ne 2 ]; then
    echo "$name failed (exit $code), see $out/$name.log" >&2
    exit "$code"
  fi
}
run cables parameter_files/waterbeam_cables.prm "$@"
run no_cables parameter_files/waterbeam_bending.prm \
  --set "Chambers/Chamber 3/Filling=liquid and gas" \
  --set "Chambers/Chamber 3/Gas/Seal time=2" \
  --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min(max(t-1,0),1)" "$@"
/usr/bin/python3 "$root/scripts/plot_bending.py" --out "$out/bending" \
  --title "Waterbeam, chamber 2 water-filled, with and without the spiral cables" \
  "with the cables:$out/cables:2:4:1" "without cables:$out/no_cables:2:4:1"
/usr/bin/python3 "$root/scripts/plot_cables.py" "$out/cables" --out "$out/cables" \
  --title "Spiral cables of the waterbeam at the end of the loading" 1 2
if command -v pvbatch > /dev/null; then
  render=(pvbatch)
  [ -z "${DISPLAY:-}" ] && command -v xvfb-run > /dev/null &&
    render=(xvfb-run -a -s "-screen 0 1920x1080x24" pvbatch)
  "${render[@]}" "$root/scripts/render_state.py" "$out/cables" "$out/cables_state.png" \
    --title "waterbeam with spiral cables, last converged state" 2>/dev/null |
    grep written || echo "no picture (pvbatch failed)"
else
  echo "pvbatch not found: install paraview (and xvfb) for a picture of the deformed beam"
fi
