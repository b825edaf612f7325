#!/bin/bash
# Wrinkling (tension field theory, doc/theory.md §2.1) on the paper's
# airbeam at 1 bar under a mid-span force (parameter_files/
# airbeam_wrinkling.prm):
# 1. cost where taut: the inflation (stage 1, the same path and Newton
#    iterations) with Wrinkling = none and = tension field at 3, 4 and 5
#    refinements: wall time, peak memory, assembly seconds per Newton
#    iteration (the plain law cannot follow the wrinkling path: it carries
#    compression and fails at 10.1 kN, 2 refinements lower);
# 2. Newton iterations and wall time per iteration per step before and
#    after wrinkling starts, and the collapse load, along the whole path to 0.25 m (4 refinements), with
#    the load-deflection plot (scripts/plot_wrinkling.py) in $OUT;
# 3. the cantilever tube of tests/wrinkling_tube continued through its
#    limit point (tip deflection 0.25 L).
# Usage: benchmarks/wrinkling/run.sh [OUT]   (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
source "$root/scripts/mpi_environment.sh"
out="${1:-$(mktemp -d)}"
mkdir -p "$out"
scene="$root/parameter_files/airbeam_wrinkling.prm"
quiet=(--set "Output/Quiet=true" --set "Output/Write VTU=false")

echo "## 1. Cost where taut: the inflation (1 rank)"
echo
echo "| refinements | dofs | wrinkling | wall s | peak MB | steps | Newton iterations | assembly s per iteration |"
echo "|---|---|---|---|---|---|---|---|"
for r in 3 4 5; do
  for w in none "tension field"; do
    d="$out/cost-$r-${w// /_}"
    /usr/bin/time -f "%e %M" -o "$out/time" "$pneuma" "$scene" "${quiet[@]}" \
      --set "Geometry/Global refinements=$r" --set "Output/Directory=$d" \
      --set "Materials/Region 0/Wrinkling=$w" \
      --set "Load stepping/Stage end times=1" --set "Load stepping/Control=load" \
      --set "Load stepping/Path following/Target monitor value=" > /dev/null
    read -r wall kb < <(tail -n 1 "$out/time")
    /usr/bin/python3 - "$d/summary.json" "$r" "$w" "$wall" "$((kb / 1024))" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
r, w, wall, mb = sys.argv[2:]
a = s["timings"]["assembly"] / s["newton_iterations"]
print(f"| {r} | {s['dofs']} | {w} | {wall} | {mb} | {s['steps']} | "
      f"{s['newton_iterations']} | {a:.4f} |")
PY
  done
done

echo
echo "## 2. The whole path (4 refinements, 1 rank)"
echo
d="$out/path"
/usr/bin/time -f "%e %M" -o "$out/time" "$pneuma" "$scene" \
  --set "Output/Directory=$d" --set "Output/Quiet=true" > /dev/null || true
read -r wall kb < <(tail -n 1 "$out/time")
/usr/bin/python3 "$here/path_table.py" "$d" "$wall" "$((kb / 1024))"
/usr/bin/python3 "$root/scripts/plot_wrinkling.py" "$d" --force 10000 \
  --wrinkling 3822 --collapse 7645 > /dev/null
echo
echo "Plot: $d/wrinkling.png"

echo
echo "## 3. Cantilever tube through its limit point"
echo
d="$out/tube"
/usr/bin/time -f "%e %M" -o "$out/time" "$pneuma" "$here/cantilever_tube.prm" \
  --set "Output/Directory=$d" "${quiet[@]}" > /dev/null || true
read -r wall kb < <(tail -n 1 "$out/time")
/usr/bin/python3 "$here/tube_table.py" "$d" "$wall"
