#!/bin/bash
# Membrane-to-membrane contact benchmark (issue "Membranes that touch"): the
# cost of the surface contact (its assembly: projections of every point onto
# its candidate cells, the penalty force and its exact tangent; and its
# search: the R-tree of the cells' boxes, renewed at each load step and
# checked at each converged state) per Newton iteration, against the
# membrane's own assembly, and the search's share.
# Scene: parameter_files/two_tubes_pressed.prm (two inflated tubes pressed
# together by two plates; one two-sided pair, every cell of each tube a
# candidate side), Q1, Global refinements 3, 4, 5 (4 096, 16 384 and
# 65 536 cells), 1 and 2 ranks: the inflation (the tubes grow into each
# other and the pair engages) and the first two steps of the pressing
# (t = 1.4; the whole pressing on 65 536 cells would take an hour here).
# "membrane s" = all assemblies (with the residual-only ones of the line
# search) minus the surface contact's; the obstacles' terms run inside the
# membrane's cell loop and count as membrane. The waterbeam bending scene
# at three meshes on 1 and 2 ranks is benchmarks/scenes/run.sh bending.
# Usage: benchmarks/contact/surfaces.sh [REFINEMENTS...]   (default 3 4 5;
# from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
source "$root/scripts/mpi_environment.sh"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
work="$here/out"
mkdir -p "$work"
cd "$root"
echo "| cells | ranks | dofs | contact points (active) | Newton its | membrane s | surface contact s | search s | contact / membrane | search / contact | contact ms per iteration | linear solve s | wall s | peak MB |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(3 4 5)
for refinements in "${sizes[@]}"; do
  for np in 1 2; do
    rm -rf "$work/run"
    /usr/bin/time -f "%e %M" -o "$work/time" \
      mpirun --bind-to none -np "$np" "$pneuma" \
      parameter_files/two_tubes_pressed.prm \
      --set "Geometry/Global refinements=$refinements" \
      --set "Discretisation/Polynomial degree=1" \
      --set "Load stepping/Stage end times=1, 1.4" \
      --set "Output/Directory=$work/run" --set "Output/Write VTU=false" \
      --set "Output/Quiet=true" > "$work/log" 2>&1
    read -r wall kb < <(awk 'NF { l = $0 } END { print l }' "$work/time")
    /usr/bin/python3 - "$root/scripts" "$work/run" "$np" "$wall" "$kb" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import pneuma_outputs
directory, ranks, wall, kb = sys.argv[2:]
s = pneuma_outputs.summary(directory)
t = s["timings"]
contact = t.get("surface contact", 0.)
search = t.get("surface contact search", 0.)
membrane = t.get("assembly", 0.) + t.get("residual assembly", 0.) - contact
pair = s["surface_contact"][0]
its = s["newton_iterations"]
print("| %d | %s | %d | %d (%d) | %d | %.2f | %.2f | %.3f | %.0f %% | %.0f %% "
      "| %.1f | %.1f | %s | %.0f |" % (
          s["cells"], ranks, s["dofs"], pair["points"], pair["active_points"],
          its, membrane, contact, search, 100 * (contact + search) / membrane,
          100 * search / (contact + search), 1e3 * (contact + search) / its,
          t.get("linear solve", 0.), wall, int(kb) / 1024))
PY
  done
done
rm -f "$work/time" "$work/log"
rm -rf "$work/run"
