#!/bin/bash
# Wrinkling (tension field theory, doc/theory.md §2.1) on the paper's
# airbeam at 1 bar under a mid-span force (parameter_files/
# airbeam_wrinkling.prm):
# 1. cost where taut: the inflation (stage 1, the same path and Newton
#    iterations) with Wrinkling = none, = tension field, and = tension
#    field smoothed over 1e-5 (Wrinkling smoothing) at 3, 4 and 5
#    refinements: wall time, peak memory, assembly seconds per Newton
#    iteration (the plain law cannot follow the wrinkling path: it carries
#    compression and fails at 10.1 kN, 2 refinements lower);
# 2. Newton iterations and wall time per iteration per step before and
#    after wrinkling starts, and the collapse load, along the whole path to 0.25 m (4 refinements), with
#    the load-deflection plot (scripts/plot_wrinkling.py) in $OUT;
# 3. the cantilever tube of tests/wrinkling_tube continued through its
#    limit point (tip deflection 0.25 L);
# 4. Newton through state changes: Wong & Pellegrino's free-edged sheet
#    (tests/shear_sheet) at residual stiffness 1e-3 and 1e-6, exact and
#    smoothed.
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
  for w in none "tension field" "smoothed"; do
    d="$out/cost-$r-${w// /_}"
    law=$w zeta=0
    [ "$w" = smoothed ] && law="tension field" zeta=1e-5
    /usr/bin/time -f "%e %M" -o "$out/time" "$pneuma" "$scene" "${quiet[@]}" \
      --set "Geometry/Global refinements=$r" --set "Output/Directory=$d" \
      --set "Materials/Region 0/Wrinkling=$law" \
      --set "Materials/Region 0/Wrinkling smoothing=$zeta" \
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

echo
echo "## 4. Newton through state changes: the free-edged sheet in shear"
echo
echo "| residual stiffness | smoothing | exit | steps | cut-backs | Newton iterations | wall s | top edge F_x N |"
echo "|---|---|---|---|---|---|---|---|"
for case in "1e-3 0" "1e-6 0" "1e-6 1e-5" "1e-3 1e-5"; do
  read -r eps zeta <<< "$case"
  d="$out/sheet-$eps-$zeta"
  code=0
  /usr/bin/time -f "%e %M" -o "$out/time" timeout 300 "$pneuma" \
    "$here/shear_sheet.prm" "${quiet[@]}" --set "Output/Directory=$d" \
    --set "Materials/Region 0/Wrinkling residual stiffness=$eps" \
    --set "Materials/Region 0/Wrinkling smoothing=$zeta" > /dev/null || code=$?
  read -r wall kb < <(tail -n 1 "$out/time")
  /usr/bin/python3 - "$d/summary.json" "$eps" "$zeta" "$code" "$wall" <<'PY'
import json, sys
path, eps, zeta, code, wall = sys.argv[1:]
try:
    s = json.load(open(path))
except OSError:
    print(f"| {eps} | {zeta} | {code} | | | | {wall} | |")
    sys.exit(0)
f = s["boundary_3_reaction"][0] if code == "0" else float("nan")
print(f"| {eps} | {zeta} | {code} | {s['steps']} | {s['cutbacks']} | "
      f"{s['newton_iterations']} | {wall} | {f:.4f} |")
PY
done
