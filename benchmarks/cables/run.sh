#!/bin/bash
# Cable benchmarks (issue "Cables"): error against the reference, wall time
# and peak memory versus the number of elements, for both elements.
#   1. cable element: the elastic V7 catenary (EA = 1e4 N, started
#      stress-free as a V, the hanging shape found by Newton's pseudo-time
#      continuation): error of the horizontal force H (4.685299 N);
#   2. solid-beam element: the same catenary with a nearly vanishing
#      bending stiffness (pinned ends), against the same reference;
#   3. solid-beam element: cantilever under a tip force (small deflection):
#      error of the tip deflection against P L^3/(3EI) + P L/(GA).
# Usage: benchmarks/cables/run.sh   (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
measure() { # pneuma arguments; prints wall s, peak MB
  /usr/bin/time -f "%e %M" -o time.txt "$pneuma" "$@" > /dev/null
  read -r wall kb < time.txt
  echo "$wall $((kb / 1024))"
}
field() { # summary.json value
  grep -o "\"$2\": [-0-9.e+]*" "$1/summary.json" | head -1 | awk '{print $NF}'
}
array() { # summary.json array entry: file, key, index
  grep -o "\"$2\": \[[^]]*\]" "$1/summary.json" | head -1 |
    sed 's/.*\[//; s/\]//' | awk -F', ' -v i="$3" '{print $(i+1)}'
}
echo "## Cable element: elastic catenary (EA = 1e4 N, from a V)"
echo "| elements | dofs | Newton its | wall s | peak MB | H [N] | error |"
echo "|---|---|---|---|---|---|---|"
for n in 16 32 64 128 256; do
  read -r wall mb < <(measure "$root/parameter_files/catenary.prm" \
    --set "Cables/Cable 1/Number of elements=$n" \
    --set "Output/Directory=$here/out/catenary" --set "Output/Write VTU=false" \
    --set "Newton/Maximum iterations=100")
  H=$(array out/catenary start_reaction 0)
  printf "| %s | %s | %s | %s | %s | %.6f | %+.2e |\n" "$n" \
    "$(field out/catenary dofs)" "$(field out/catenary newton_iterations)" \
    "$wall" "$mb" "$(awk -v h="$H" 'BEGIN{print -h}')" \
    "$(awk -v h="$H" 'BEGIN{print (-h-4.685299)/4.685299}')"
done
echo
echo "## Solid-beam element: the same catenary (a = 5e-5 m, EA = 1e4 N, EI = 6e-6 N m^2, pinned ends)"
echo "| elements | dofs | Newton its | wall s | peak MB | H [N] | error |"
echo "|---|---|---|---|---|---|---|"
E_beam=$(awk 'BEGIN{pi=atan2(0,-1); print 1e4/(pi*5e-5*5e-5)}')
for n in 16 32 64 128 256; do
  read -r wall mb < <(measure "$root/parameter_files/catenary.prm" \
    --set "Cables/Cable 1/Number of elements=$n" \
    --set "Cables/Cable 1/Element=solid beam" \
    --set "Cables/Cable 1/solid beam/Poisson's ratio=0" \
    --set "Cables/Cable 1/Section semi-axes=5e-5" \
    --set "Cables/Cable 1/Young's modulus=$E_beam" \
    --set "Cables/Cable 1/Start support=pinned" \
    --set "Cables/Cable 1/End support=pinned" \
    --set "Output/Directory=$here/out/catenary_beam" --set "Output/Write VTU=false" \
    --set "Newton/Maximum iterations=100")
  H=$(array out/catenary_beam start_reaction 0)
  printf "| %s | %s | %s | %s | %s | %.6f | %+.2e |\n" "$n" \
    "$(field out/catenary_beam dofs)" "$(field out/catenary_beam newton_iterations)" \
    "$wall" "$mb" "$(awk -v h="$H" 'BEGIN{print -h}')" \
    "$(awk -v h="$H" 'BEGIN{print (-h-4.685299)/4.685299}')"
done
echo
echo "## Solid-beam element: cantilever, tip force (Timoshenko reference)"
echo "| elements | dofs | Newton its | wall s | peak MB | tip deflection [m] | error |"
echo "|---|---|---|---|---|---|---|"
ref=$(awk 'BEGIN{pi=atan2(0,-1); a=0.02; E=2e11; I=pi*a^4/4; A=pi*a*a;
             print 1/(3*E*I) + 1/(E/2*A)}')
for n in 4 8 16 32 64 128; do
  read -r wall mb < <(measure cantilever.prm --set "Cables/Cable 1/Number of elements=$n")
  w=$(array out/cantilever end_u 1)
  printf "| %s | %s | %s | %s | %s | %.6e | %+.2e |\n" "$n" \
    "$(field out/cantilever dofs)" "$(field out/cantilever newton_iterations)" \
    "$wall" "$mb" "$w" "$(awk -v w="$w" -v r="$ref" 'BEGIN{print (w-r)/r}')"
done
