#!/bin/bash
# Contact benchmark (issue "Contact"): the cost of the contact terms (search
# + projections + assembly) per Newton step relative to the membrane
# assembly, for 100, 500 and 2000 cable elements on a ~50k-cell membrane
# (the airbeam tube, Q1, 51 200 cells, held fixed; a prestressed helix at
# 60 degrees pressed onto it; benchmarks/contact/helix_on_tube.prm).
# Target: contact under 25 % of the membrane assembly at 500 elements.
# Usage: benchmarks/contact/run.sh   (from anywhere; builds if needed)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
[ -x "$root/build/pneuma" ] || "$root/scripts/build.sh" > /dev/null
pneuma="$root/build/pneuma"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
timing() { # summary.json timer
  grep -o "\"$1\": [0-9][0-9.e+-]*" out/helix/summary.json | head -1 | awk '{print $NF}'
}
field() {
  grep -o "\"$1\": [0-9][0-9.e+-]*" out/helix/summary.json | head -1 | awk '{print $NF}'
}
for normal in facet smoothed; do
echo
echo "Master normal = $normal"
echo
echo "| cable elements | contact points (active) | Newton its | membrane assembly s | contact s | search s | contact / membrane | linear solve s | wall s | peak MB |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for n in 100 500 2000; do
  /usr/bin/time -f "%e %M" -o time.txt "$pneuma" helix_on_tube.prm \
    --set "Cables/Cable 1/Number of elements=$n" \
    --set "Contact/Pair 1/Master normal=$normal" > /dev/null
  read -r wall kb < time.txt
  a=$(timing assembly); c=$(timing contact); k=$(timing "cable assembly")
  srch=$(timing "contact search"); ls=$(timing "linear solve")
  m=$(awk -v a="$a" -v c="$c" -v k="$k" 'BEGIN{print a-c-k}')
  printf "| %s | %s (%s) | %s | %.3f | %.3f | %.3f | %.1f %% | %.1f | %s | %s |\n" \
    "$n" "$(field points)" "$(field active_points)" "$(field newton_iterations)" \
    "$m" "$c" "${srch:-0}" "$(awk -v m="$m" -v c="$c" -v s="${srch:-0}" 'BEGIN{print 100*(c+s)/m}')" \
    "$ls" "$wall" "$((kb / 1024))"
done
done
rm -f time.txt
