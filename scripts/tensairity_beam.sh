#!/bin/bash
# Luchsinger's basic Tensairity element on the paper's airbeam
# (parameter_files/tensairity_beam.prm): the airbeam of Figure 7 with its
# compression element and two opposite helical cables anchored to the end
# plates, inflated to 2 bar absolute and sealed, then the line load on the
# compression element at mid-span under displacement control to 0.15 m.
# The airbeam of Figure 7 (parameter_files/airbeam_figure7.prm) runs at the
# same pressure on the same mesh (Q2, 544 cells) for comparison.
# Writes output/tensairity_beam/{tensairity,airbeam}/ and tensairity.csv,
# tensairity.png (scripts/plot_bending.py): force against the deflection
# under the load and at the bottom at mid-span, the gas pressure and
# volume; the cable tensions in the summary; pictures of the last states
# where ParaView is installed. Extra arguments are passed to both runs.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/tensairity_beam
mkdir -p "$out"
source "$root/scripts/scene_tools.sh"
scene_run tensairity parameter_files/tensairity_beam.prm "$@"
scene_run airbeam parameter_files/airbeam_figure7.prm \
  --set "Chambers/Chamber 1/Gas/Pressure/Function constants=p0=1e5" \
  --set "Discretisation/Polynomial degree=2" \
  --set "Geometry/Global refinements=2" "$@"
/usr/bin/python3 "$root/scripts/plot_bending.py" --out "$out/tensairity" \
  --title "Tensairity element against the airbeam of Figure 7 (2 bar absolute, sealed)" \
  "Tensairity (strut + 2 helices):$out/tensairity:1:0:1" \
  "airbeam of Figure 7 (strut):$out/airbeam:1:0:1"
/usr/bin/python3 - "$out/tensairity" <<'PY'
import sys
sys.path.insert(0, "scripts")
import pneuma_outputs as po
s = po.summary(sys.argv[1])
for c in s["cables"]:
    name = "compression element" if c["cable"] == 1 else "helix %d" % (c["cable"] - 1)
    print("%s: force %.0f to %.0f N" % (name, c["min_force"], c["max_force"]))
for p in s["contact"]:
    print("contact of helix %d: %d of %d points active, %.0f N in all"
          % (p["pair"], p["active_points"], p["points"], p["total_force"]))
PY
scene_pictures tensairity airbeam
