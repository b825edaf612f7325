#!/bin/bash
# The membrane's cell loop on several threads (deal.II's WorkStream, with
# the chambers' wall terms in it; core/threads.h), and the contact points'
# penalty terms (tensairity_scene: two cable pairs, 240 points in contact,
# added in point order after the threads): one rank with 1 and with
# 2 threads ends with the same summary.json (every number to 1e-9
# relative). The sums over cells are formed in cell order on any number of
# threads; what differs is deal.II's FEValues shortcut for translated cells
# (CellSimilarity, used on one thread only) in the reference data, at
# round-off.
# Usage: check_threads.sh PNEUMA_BINARY SOURCE_DIR [PYTHON]
pneuma="$1" src="$2" python="${3:-/usr/bin/python3}"
compare="$python $src/tests/compare_summaries.py"
fail=0
# The BLAS keeps one thread: the cell loop's threads are what is compared.
export OPENBLAS_NUM_THREADS=1
for prm in chambers_liquid_gas_mpi tensairity_scene; do
  for n in 1 2; do
    rm -rf "$prm-threads-$n"
    if ! DEAL_II_NUM_THREADS=$n "$pneuma" "$src/tests/$prm.prm" \
        --set "Output/Directory=$prm-threads-$n" --set "Output/Quiet=true" \
        > "$prm-threads-$n.log" 2>&1; then
      echo "FAIL $prm on $n thread(s): $(tail -3 "$prm-threads-$n.log")"
      fail=1
    fi
  done
  echo -n "$prm, 2 threads against 1: "
  $compare "$prm-threads-1/summary.json" "$prm-threads-2/summary.json" 1e-9 || fail=1
done
exit $fail
