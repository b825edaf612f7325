#!/bin/bash
# Cost of the stability indicator (Stability/Check inertia: one assembly
# and one MUMPS LDL^T factorization per converged step, solvers/
# stability.h) on the inflated closed cylinder of benchmarks/
# inflated_cylinder (one load step, 6 Newton iterations) at three sizes,
# on 1 and 2 ranks: wall time and peak memory with and without it, the
# time of the check from summary.json, and its share of the run.
# Usage: benchmarks/stability/run.sh   (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
source "$root/scripts/mpi_environment.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "| refinements | dofs | ranks | wall s (off) | wall s (on) | peak MB (off) | peak MB (on) | check s | share of run | negative eigenvalues |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for r in 3 4 5; do
  for n in 1 2; do
    declare -A wall mb
    for c in false true; do
      /usr/bin/time -f "%e %M" -o "$work/time" mpirun -np "$n" "$pneuma" \
        "$root/benchmarks/inflated_cylinder/cylinder.prm" \
        --set "Geometry/Global refinements=$r" --set "Output/Directory=$work/$c" \
        --set "Output/Quiet=true" --set "Output/Write VTU=false" \
        --set "Stability/Check inertia=$c" > /dev/null
      read -r w k < "$work/time"
      wall[$c]=$w mb[$c]=$((k / 1024))
    done
    /usr/bin/python3 - "$work/true/summary.json" "$r" "$n" "${wall[false]}" "${wall[true]}" \
      "${mb[false]}" "${mb[true]}" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
r, n, w0, w1, m0, m1 = sys.argv[2:]
check = s["timings"]["stability"]
print(f"| {r} | {s['dofs']} | {n} | {w0} | {w1} | {m0} | {m1} | {check:.2f} | "
      f"{100 * check / float(w1):.0f} % | {s['negative_eigenvalues']} |")
PY
  done
done
