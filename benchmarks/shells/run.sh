#!/bin/bash
# Shells with bending (issue 48, doc/theory.md §21): the cost of the bending
# against the membrane alone on the airbeam tube inflated to 1 bar
# (benchmarks/shells/tube.prm, Q2) at 4 and 5 refinements (8 704 and
# 34 816 cells): the first load step (to 0.25 bar, from the stress-free
# tube) with membrane walls and with Bending = shell on every region:
# wall time, peak memory, Newton iterations, assembly seconds per
# iteration (the cells' and the edges' terms; the bending's share is the
# difference) and linear-solve seconds per iteration, and the bending
# energy's share of the walls' strain energy. WALLS may also name
# membrane-assumed and shell-displacement (Membrane strains = assumed on a
# membrane, = displacement on a shell: the cost of the assumed strains).
# Usage: [REFINEMENTS="4 5"] [WALLS="membrane shell"] benchmarks/shells/run.sh [OUT]
# (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
source "$root/scripts/mpi_environment.sh"
out="${1:-$(mktemp -d)}"
mkdir -p "$out"
quiet=(--set "Output/Quiet=true" --set "Output/Write VTU=false"
       --set "Load stepping/Stage end times=0.25")

echo "| refinements | cells | dofs | walls | wall s | peak MB | Newton iterations | assembly s per iteration | linear solve s per iteration | bending / strain energy |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for r in ${REFINEMENTS:-4 5}; do
  for walls in ${WALLS:-membrane shell}; do
    d="$out/tube-$r-$walls"
    bending=none strains=auto
    case "$walls" in
      shell) bending=shell ;;
      shell-displacement) bending=shell strains=displacement ;;
      membrane-assumed) strains=assumed ;;
    esac
    /usr/bin/time -f "%e %M" -o "$out/time" "$pneuma" "$here/tube.prm" \
      "${quiet[@]}" --set "Geometry/Global refinements=$r" \
      --set "Output/Directory=$d" \
      --set "Materials/Region 0/Bending=$bending" \
      --set "Materials/Region 1/Bending=$bending" \
      --set "Materials/Region 2/Bending=$bending" \
      --set "Materials/Region 0/Membrane strains=$strains" \
      --set "Materials/Region 1/Membrane strains=$strains" \
      --set "Materials/Region 2/Membrane strains=$strains" > /dev/null
    read -r wall kb < <(tail -n 1 "$out/time")
    /usr/bin/python3 - "$d/summary.json" "$r" "$walls" "$wall" \
      "$((kb / 1024))" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
r, walls, wall, mb = sys.argv[2:]
n = s["newton_iterations"]
t = s["timings"]
share = "–"
if "bending_energy" in s:
    b, m = s["bending_energy"], s["membrane_energy"]
    share = f"{b / (b + m):.2e}"
print(f"| {r} | {s['cells']} | {s['dofs']} | {walls} | {wall} | {mb} | {n} | "
      f"{t['assembly'] / n:.3f} | {t['linear solve'] / n:.3f} | {share} |")
PY
  done
done
