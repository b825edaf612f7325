#!/bin/bash
# Explicit-dynamics benchmarks (issue 49): the cost of one explicit step.
#   1. a sealed gas sphere (sphere.prm), Q1 and Q2, three mesh sizes, 1 and
#      2 ranks: microseconds per cell and step (wall, and times the 2 cores
#      every run uses: 1 rank runs the cell loop on 2 threads), from two
#      runs of different lengths (their difference: no setup, no static
#      stage);
#   2. the waterbeam of parameter_files/waterbeam_filling.prm (Gmsh mesh,
#      Q1, rigid end plates, three chambers) with gas only and with water in
#      chamber 2: milliseconds per step and steps per second, 1 and 2 ranks.
# Usage: benchmarks/explicit/run.sh [pneuma executable]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
source "$root/scripts/mpi_environment.sh"
pneuma="${1:-$root/build/pneuma}"
[ -x "$pneuma" ] || { "$root/scripts/build.sh" > /dev/null; pneuma="$root/build/pneuma"; }
work="$here/out"
mkdir -p "$work"
run() { # ranks, directory, then pneuma arguments (from the project root)
  local n=$1 dir=$2
  shift 2
  (cd "$root" && mpirun -np "$n" "$pneuma" "$@" --set "Output/Directory=$dir" \
    --set "Output/Write VTU=false" --set "Output/Quiet=true" > /dev/null)
}
json() { # directory, key
  /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]+'/summary.json'))[sys.argv[2]])" "$1" "$2"
}
per_step() { # ranks, short end, long end, then arguments: prints s/step, steps, cells
  local n=$1 t1=$2 t2=$3
  shift 3
  run "$n" "$work/a" "$@" --set "Load stepping/Stage end times=$t1"
  run "$n" "$work/b" "$@" --set "Load stepping/Stage end times=$t2"
  local w1 w2 s1 s2
  w1=$(json "$work/a" wall_seconds); w2=$(json "$work/b" wall_seconds)
  s1=$(json "$work/a" explicit_steps); s2=$(json "$work/b" explicit_steps)
  awk -v a="$w1" -v b="$w2" -v s="$s1" -v t="$s2" 'BEGIN{printf "%.6e %d", (b-a)/(t-s), t-s}'
  echo " $(json "$work/b" cells)"
}
echo "## Gas sphere: cost per cell and step"
echo "| degree | refinements | cells | ranks | steps timed | ms/step | us per cell-step (wall) | x 2 cores |"
echo "|---|---|---|---|---|---|---|---|"
for p in 1 2; do
  for r in 3 4 5; do
    [ "$p" = 2 ] && [ "$r" = 5 ] && continue
    rr=$r; [ "$p" = 2 ] && rr=$((r - 1)) && [ "$rr" -lt 2 ] && continue
    for n in 1 2; do
      read -r s steps cells < <(per_step "$n" "1, 1.05" "1, 1.25" \
        benchmarks/explicit/sphere.prm --set "Discretisation/Polynomial degree=$p" \
        --set "Geometry/Global refinements=$rr")
      awk -v p="$p" -v r="$rr" -v c="$cells" -v n="$n" -v s="$s" -v k="$steps" \
        'BEGIN{printf "| Q%d | %d | %d | %d | %d | %.3f | %.3f | %.3f |\n", p, r, c, n, k, s*1e3, s/c*1e6, 2*s/c*1e6}'
    done
  done
done
echo
echo "## Waterbeam (refinement 0, Q1): cost per step"
echo "| case | ranks | cells | steps timed | ms/step | steps/s |"
echo "|---|---|---|---|---|---|"
wb=(parameter_files/waterbeam_filling.prm --set "Load stepping/Strategy=explicit"
    --set "Loads/Gravity vector/Function expression=0; 0; -9.81"
    --set "Chambers/Chamber 1/Gas/Pressure/Function expression=1e5*min(t/0.01,1)"
    --set "Chambers/Chamber 3/Gas/Pressure/Function expression=1e5*min(t/0.01,1)"
    --set "Chambers/Chamber 1/Gas/Seal time=0.01")
water=(--set "Chambers/Chamber 3/Filling=liquid and gas"
       --set "Chambers/Chamber 3/Gas/Seal time=-1"
       --set "Chambers/Chamber 3/Liquid/Volume/Function expression=0.005*min((t+0.001)/0.011,1)")
for n in 1 2; do
  read -r s steps cells < <(per_step "$n" 2e-5 1.2e-4 "${wb[@]}" \
    --set "Chambers/Chamber 3/Gas/Seal time=0.01")
  awk -v n="$n" -v c="$cells" -v s="$s" -v k="$steps" \
    'BEGIN{printf "| gas | %d | %d | %d | %.2f | %.0f |\n", n, c, k, s*1e3, 1/s}'
  read -r s steps cells < <(per_step "$n" 2e-5 1.2e-4 "${wb[@]}" "${water[@]}")
  awk -v n="$n" -v c="$cells" -v s="$s" -v k="$steps" \
    'BEGIN{printf "| water | %d | %d | %d | %.2f | %.0f |\n", n, c, k, s*1e3, 1/s}'
done
