#!/bin/bash
# Cost of the eigen analysis (solvers/eigen_analysis.h) on the inflated
# closed cylinder of benchmarks/inflated_cylinder (Q1, one load step to
# 1 bar, then 10 modes of the final state): the tangent's lowest
# eigenvalues and the natural frequencies (membrane density 1000 kg/m^3),
# at two sizes, on 1 and 2 ranks. Per run: the wall time and peak memory
# (largest process, /usr/bin/time) without and with the analysis, the
# analysis' own time, the time of its one LDL^T factorization, their
# ratio, ARPACK's restarts and substitutions, and the lowest value.
# Usage: benchmarks/stability/eigen.sh   (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
source "$root/scripts/mpi_environment.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run() { # directory, ranks, refinements, more settings...
  /usr/bin/time -f "%e %M" -o "$work/time" mpirun -np "$2" "$pneuma" \
    "$root/benchmarks/inflated_cylinder/cylinder.prm" \
    --set "Geometry/Global refinements=$3" --set "Output/Directory=$work/$1" \
    --set "Output/Quiet=true" --set "Output/Write VTU=false" \
    --set "Stability/Check inertia=false" \
    --set "Materials/Region 0/Density=1000" "${@:4}" > /dev/null
  cat "$work/time"
}
echo "| refinements | dofs | cells | ranks | type | wall s (none) | wall s (with) | peak MB (none) | peak MB (with) | analysis s | factorization s | analysis / factorization | restarts | substitutions | lowest value |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for r in 4 5; do
  for n in 1 2; do
    read -r w0 k0 <<< "$(run none "$n" "$r")"
    for type in tangent modal; do
      read -r w1 k1 <<< "$(run "$type" "$n" "$r" --set "Eigen analysis/Type=$type" \
                                   --set "Eigen analysis/Number of modes=10")"
      /usr/bin/python3 - "$work/$type/summary.json" "$r" "$n" "$type" "$w0" "$w1" \
        "$((k0 / 1024))" "$((k1 / 1024))" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
r, n, t, w0, w1, m0, m1 = sys.argv[2:]
e, f = s["eigen_seconds"], s["eigen_factorization_seconds"]
m = s["eigen_modes"][0]
low = f"{m['frequency']:.3f} Hz" if t == "modal" else f"{m['eigenvalue']:.4g} N/m"
print(f"| {r} | {s['dofs']} | {s['cells']} | {n} | {t} | {w0} | {w1} | {m0} | {m1} | "
      f"{e:.2f} | {f:.2f} | {e / f:.1f} | {s['eigen_iterations']} | "
      f"{s['eigen_substitutions']} | {low} |")
PY
    done
  done
done
