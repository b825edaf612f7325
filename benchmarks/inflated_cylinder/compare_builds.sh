#!/usr/bin/env bash
# Side-by-side timing of two pneuma builds on the 47k-cell closed cylinder
# (Global refinements 5, 9 coarse cells along the axis: 47 104 cells,
# 141 318 dofs), runs alternating so that both see the same machine.
#
# Usage: compare_builds.sh OLD_BIN OLD_PRM NEW_BIN NEW_PRM [RUNS] [LAUNCH]
#   OLD_PRM / NEW_PRM: the cylinder.prm each build reads (the parameter
#   layout may differ between builds); RUNS per build [5]; LAUNCH e.g.
#   "mpirun -np 2" [none]. Prints the wall time of every run (from
#   /usr/bin/time), the median per build, the ratio new/old, and dR.
set -euo pipefail
OLD_BIN=$1 OLD_PRM=$2 NEW_BIN=$3 NEW_PRM=$4 RUNS=${5:-5} LAUNCH=${6:-}
source "$(dirname "$0")/../../scripts/mpi_environment.sh"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
old_geometry=("--set" "Geometry/Global refinements=5")
run() { # bin prm label k extra...
  local bin=$1 prm=$2 label=$3 k=$4; shift 4
  /usr/bin/time -f "%e %M" -o "$WORK/$label.$k.time" $LAUNCH "$bin" "$prm" \
    --set "Output/Directory=$WORK/$label.$k" --set "Output/Quiet=true" \
    "${old_geometry[@]}" "$@" > /dev/null
}
for k in $(seq "$RUNS"); do
  run "$OLD_BIN" "$OLD_PRM" old "$k" \
    --set "Geometry/closed cylinder/Cells along length=9"
  run "$NEW_BIN" "$NEW_PRM" new "$k" \
    --set "Geometry/closed cylinder/Cells along length=9"
done
python3 - "$WORK" "$RUNS" <<'PY'
import json, statistics, sys
work, runs = sys.argv[1], int(sys.argv[2])
med = {}
for label in ("old", "new"):
    walls = []
    for k in range(1, runs + 1):
        wall, kb = open(f"{work}/{label}.{k}.time").read().split()
        walls.append(float(wall))
    s = json.load(open(f"{work}/{label}.1/summary.json"))
    mp = s["monitor_points"][0]
    u = mp.get("u", mp.get("displacement"))
    med[label] = statistics.median(walls)
    print(f"{label}: walls {walls} s, median {med[label]:.2f} s, peak "
          f"{int(kb) / 1024:.0f} MB, dR {1e3 * u[1]:.6f} mm, "
          f"{s['newton_iterations']} Newton iterations")
print(f"new/old median wall: {med['new'] / med['old']:.3f}")
PY
