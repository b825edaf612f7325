#!/usr/bin/env bash
# Side-by-side timing of two pneuma builds on Figure 11 at its target size
# (benchmarks/scenes/run.sh `target`: Gmsh n = 26, 49 608 cells, 250
# elements per cable, to 3 cm), runs alternating so that both see the same
# machine.
#
# Usage: compare_builds.sh OLD_ROOT NEW_ROOT [RUNS] [RANKS]
#   OLD_ROOT / NEW_ROOT: source trees with a built build/pneuma (each reads
#   its own parameter_files/waterbeam_cables.prm); RUNS per build [3];
#   RANKS [2]; OLD_BIN / NEW_BIN in the environment replace
#   ROOT/build/pneuma (e.g. a separate build directory). Prints the wall time and peak memory of every run (from
#   /usr/bin/time), the median per build, the ratio new/old, the final
#   deflection and the Newton iterations.
set -euo pipefail
OLD=$1 NEW=$2 RUNS=${3:-3} RANKS=${4:-2}
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../../scripts/mpi_environment.sh"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
gmsh -2 -format msh22 -setnumber n 26 "$NEW/meshes/waterbeam.geo" \
  -o "$WORK/waterbeam_26.msh" > /dev/null
OLD_BIN=${OLD_BIN:-$OLD/build/pneuma} NEW_BIN=${NEW_BIN:-$NEW/build/pneuma}
run() { # root binary label k
  local root=$1 bin=$2 label=$3 k=$4
  /usr/bin/time -f "%e %M" -o "$WORK/$label.$k.time" \
    mpirun --bind-to none -np "$RANKS" "$bin" \
    "$root/parameter_files/waterbeam_cables.prm" \
    --set "Output/Directory=$WORK/$label.$k" --set "Output/Write VTU=false" \
    --set "Output/Quiet=true" \
    --set "Geometry/gmsh/Mesh file=$WORK/waterbeam_26.msh" \
    --set "Cables/Cable 1/Number of elements=250" \
    --set "Cables/Cable 2/Number of elements=250" > "$WORK/$label.$k.log" 2>&1
}
for k in $(seq "$RUNS"); do
  run "$OLD" "$OLD_BIN" old "$k"
  run "$NEW" "$NEW_BIN" new "$k"
done
python3 - "$WORK" "$RUNS" <<'PY'
import json, statistics, sys
work, runs = sys.argv[1], int(sys.argv[2])
med = {}
for label in ("old", "new"):
    walls, peaks = [], []
    for k in range(1, runs + 1):
        wall, kb = open(f"{work}/{label}.{k}.time").read().split()[-2:]
        walls.append(float(wall))
        peaks.append(int(kb) / 1024)
    s = json.load(open(f"{work}/{label}.1/summary.json"))
    mp = s["monitor_points"][0]
    u = mp.get("u", mp.get("displacement"))
    med[label] = statistics.median(walls)
    print(f"{label}: walls {walls} s, median {med[label]:.2f} s, peak "
          f"{max(peaks):.0f} MB (largest process), u_z {1e3 * u[2]:.6f} mm, "
          f"{s['newton_iterations']} Newton iterations")
print(f"new/old median wall: {med['new'] / med['old']:.3f}")
PY
