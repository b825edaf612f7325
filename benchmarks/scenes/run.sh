#!/bin/bash
# The paper's scenes (doc/scenes.md) at three mesh sizes on 1 and 2 ranks:
# wall time, peak memory (the largest process, /usr/bin/time), load steps,
# cut-backs, Newton iterations, the end of the run, and where the time goes
# (summary.json's timings).
#   figure7     parameter_files/airbeam_figure7.prm, 2 bar absolute (the
#               hardest of the series: wrinkling to 0.15 m), Q1,
#               refinements 2, 3, 4;
#   tensairity  parameter_files/tensairity_beam.prm, Q2, refinements 2, 3
#               (on 1 refinement the support point against the spin falls
#               inside the plate: the scene needs 2 or more);
#   filling     parameter_files/waterbeam_filling.prm, water case of
#               scripts/waterbeam_filling.sh, Gmsh meshes n = 6, 12, 18;
#   bending     parameter_files/waterbeam_bending.prm, water variant of
#               scripts/waterbeam_bending.sh, the same meshes;
#   cables      parameter_files/waterbeam_cables.prm (Figure 11), Gmsh
#               meshes n = 6, 9, 12, 160 elements per cable;
#   target      the same on n = 26 (49 608 cells) with 250 elements per
#               cable: the issue's target size (the paper's LS-DYNA model).
# Ranks are not bound to cores (mpirun --bind-to none): OpenMPI binds 1 or
# 2 ranks to one core each, so one bound rank would run on one thread.
# Usage: benchmarks/scenes/run.sh [SCENE ...]   (default: all but target; builds
# if needed). Writes the tables to stdout; results.md holds a dated run.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
source "$root/scripts/mpi_environment.sh"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
work="$here/out"
mkdir -p "$work"
scenes=("$@")
[ ${#scenes[@]} -eq 0 ] && scenes=(figure7 tensairity filling bending cables)

# One run: ranks, size label, parameter file, arguments; prints a table row.
run() {
  local ranks=$1 size=$2 file=$3 code=0
  shift 3
  rm -rf "$work/run"
  /usr/bin/time -f "%e %M" -o "$work/time" \
    mpirun --bind-to none -np "$ranks" "$pneuma" \
    "$file" --set "Output/Directory=$work/run" --set "Output/Write VTU=false" \
    --set "Output/Quiet=true" "$@" > "$work/log" 2>&1 || code=$?
  read -r wall kb < <(awk 'NF { l = $0 } END { print l }' "$work/time")
  /usr/bin/python3 - "$root/scripts" "$work/run" "$size" "$ranks" "$wall" \
    "$kb" "$code" "$(head -n 1 "$work/log")" <<'PY'
import os
import sys
sys.path.insert(0, sys.argv[1])
import pneuma_outputs
directory, size, ranks, wall, kb, code, first_line = sys.argv[2:]
if not os.path.exists(directory + "/summary.json"):
    print("| %s | %s | | | | | | exit %s: %s | %s | %.0f | |"
          % (size, ranks, code, first_line, wall, int(kb) / 1024))
    sys.exit(0)
s = pneuma_outputs.summary(directory)
t = s.get("timings", {})
share = ", ".join("%s %.0f%%" % (k, 100 * v / float(wall))
                  for k, v in sorted(t.items(), key=lambda kv: -kv[1])[:3])
end = "completed" if code == "0" else \
    "exit %s at t = %.4g" % (code, s.get("final_time", float("nan")))
print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.0f | %s |" % (
    size, ranks, s["cells"], s["dofs"], s["steps"], s["cutbacks"],
    s["newton_iterations"], end, wall, int(kb) / 1024, share))
PY
}
header() {
  echo
  echo "## $1"
  echo
  echo "| size | ranks | cells | dofs | steps | cut-backs | Newton its | end | wall s | peak MB | largest shares of the wall time |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
}
mesh() { # n: the waterbeam mesh of density n
  [ -f "$work/waterbeam_$1.msh" ] ||
    gmsh -2 -format msh22 -setnumber n "$1" "$root/meshes/waterbeam.geo" \
      -o "$work/waterbeam_$1.msh" > /dev/null
  echo "$work/waterbeam_$1.msh"
}
water=(--set "Chambers/Chamber 3/Filling=liquid and gas"
       --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min(max(t-1,0),1)")
echo "pneuma $(git -C "$root" rev-parse --short HEAD), $(date -u +%F), $(nproc) cores"
for scene in "${scenes[@]}"; do
  case $scene in
    figure7)
      header "Figure 7 airbeam, 2 bar absolute, Q1, refinements 2 / 3 / 4, to 0.15 m"
      for r in 2 3 4; do for np in 1 2; do
        run "$np" "r$r" "$root/parameter_files/airbeam_figure7.prm" \
          --set "Geometry/Global refinements=$r" \
          --set "Chambers/Chamber 1/Gas/Pressure/Function constants=p0=1e5"
      done; done ;;
    tensairity)
      header "Tensairity element, Q2, refinements 2 / 3, to 0.15 m"
      for r in 2 3; do for np in 1 2; do
        run "$np" "r$r" "$root/parameter_files/tensairity_beam.prm" \
          --set "Geometry/Global refinements=$r"
      done; done ;;
    filling)
      header "Waterbeam filling, water case, Q1, Gmsh n = 6 / 12 / 18"
      for n in 6 12 18; do m=$(mesh "$n"); for np in 1 2; do
        run "$np" "n$n" "$root/parameter_files/waterbeam_filling.prm" \
          --set "Geometry/gmsh/Mesh file=$m" \
          --set "Load stepping/Stage end times=1, 2" \
          --set "Load stepping/Initial increment=0.125" \
          --set "Load stepping/Maximum increment=0.125" \
          --set "Chambers/Chamber 3/Gas/Seal time=-1" "${water[@]}"
      done; done ;;
    bending)
      header "Waterbeam bending, water variant, Q1, Gmsh n = 6 / 12 / 18, to 6 cm"
      for n in 6 12 18; do m=$(mesh "$n"); for np in 1 2; do
        run "$np" "n$n" "$root/parameter_files/waterbeam_bending.prm" \
          --set "Geometry/gmsh/Mesh file=$m" \
          --set "Chambers/Chamber 3/Gas/Seal time=2" "${water[@]}"
      done; done ;;
    cables)
      header "Waterbeam with spiral cables (Figure 11), Q1, Gmsh n = 6 / 9 / 12, to 6 cm"
      for n in 6 9 12; do m=$(mesh "$n"); for np in 1 2; do
        run "$np" "n$n" "$root/parameter_files/waterbeam_cables.prm" \
          --set "Geometry/gmsh/Mesh file=$m"
      done; done ;;
    target)
      header "Waterbeam with spiral cables at the target size: Gmsh n = 26, 250 elements per cable, to 6 cm"
      m=$(mesh 26); for np in 1 2; do
        run "$np" "n26" "$root/parameter_files/waterbeam_cables.prm" \
          --set "Geometry/gmsh/Mesh file=$m" \
          --set "Cables/Cable 1/Number of elements=250" \
          --set "Cables/Cable 2/Number of elements=250"
      done ;;
    *) echo "unknown scene $scene (figure7, tensairity, filling, bending, cables, target)" >&2
       exit 1 ;;
  esac
done
