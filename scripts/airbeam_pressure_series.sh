#!/bin/bash
# The paper's Figure 7: load-deflection curves of the airbeam for the
# pressures 1, 2, 5, 10, 20 and 40 bar. Runs parameter_files/airbeam.prm
# once per pressure (--set), with the transverse load applied in 10 steps,
# and writes output/airbeam_series/load_deflection.csv with columns
# pressure_bar, F_N, deflection_m (minus the mean u_z of the four points of
# the mid-span ring, relative to the inflated state).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
out=output/airbeam_series
mkdir -p "$out"
echo "pressure_bar,F_N,deflection_m" > "$out/load_deflection.csv"
for bar in 1 2 5 10 20 40; do
  dir="$out/p${bar}bar"
  "$root/build/pneuma" parameter_files/airbeam.prm \
    --set "Loads/Pressure/Function constants=p0=${bar}e5" \
    --set "Load stepping/Initial increment=0.1" \
    --set "Load stepping/Maximum increment=0.1" \
    --set "Output/Write VTU=false" \
    --set "Output/Directory=$dir" > "$dir.log"
  # history.csv: the ring of monitor points m0..m3 at mid-span.
  python3 - "$root/scripts" "$dir" "$bar" >> "$out/load_deflection.csv" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import pneuma_outputs
rows = pneuma_outputs.history(sys.argv[2])
def mean_uz(r):
    return sum(r[f"m{i}_u_z"] for i in range(4)) / 4.0
inflated = [r for r in rows if abs(r["time"] - 1.0) < 1e-9][0]
sys.argv[2] = sys.argv[3]
for r in rows:
    t = r["time"]
    if t >= 1.0 - 1e-9:
        print(f"{sys.argv[2]},{1000.0 * (t - 1.0):.6g},{-(mean_uz(r) - mean_uz(inflated)):.6e}")
PY
  echo "p = $bar bar done"
done
echo "written: $out/load_deflection.csv"
