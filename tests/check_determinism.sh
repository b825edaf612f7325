#!/bin/bash
# The same input on the same ranks and threads gives the same outputs, byte
# for byte, whatever else the machine does (doc/user-guide.md "Reproducible
# runs"). Each scene runs twice on one rank with 2 threads (the cell loop
# on WorkStream, OpenBLAS under MUMPS) and twice on 2 ranks (MUMPS on rank
# 0, p4est's partition, the contact points of both ranks); the second run
# of each pair shares the cores with one busy loop per core, so that the
# threads and ranks are scheduled differently. tests/compare_outputs.py
# then compares every file of the two output directories: VTU, PVTU, PVD,
# parameters.prm, history.csv without its wall_seconds column, and
# summary.json without its wall-clock entries ("*_seconds", "timings").
# Scenes: tensairity_scene (cables, contact, ties, two stages, Q2) and
# chambers_liquid_gas_mpi (gas and liquid chambers: the chamber terms in
# the cell loop, the free-surface quadrature), both with VTU output.
# Usage: check_determinism.sh PNEUMA_BINARY SOURCE_DIR [PYTHON]
pneuma="$(realpath -- "$1")" src="$(realpath -- "$2")" python="${3:-/usr/bin/python3}"
compare="$python $src/tests/compare_outputs.py"
source "$src/scripts/mpi_environment.sh"
fail=0
busy=()
stop_load() {
  for pid in "${busy[@]}"; do kill "$pid" 2> /dev/null; done
  for pid in "${busy[@]}"; do wait "$pid" 2> /dev/null; done
  busy=()
}
trap stop_load EXIT
start_load() {
  for _ in $(seq "$(nproc)"); do
    (while :; do :; done) &
    busy+=($!)
  done
}
run() { # name launcher...: the outputs in name/out (the same directory
  # name in both runs: parameters.prm records it)
  local name="$1"
  shift
  rm -rf "$name"
  mkdir -p "$name"
  if ! (cd "$name" && "$@" "$src/tests/$prm.prm" --set "Output/Directory=out" \
      --set "Output/Quiet=true" --set "Output/Write VTU=true" \
      --set "Output/Test output=false" > log 2>&1); then
    echo "FAIL $name: $(tail -3 "$name/log")"
    fail=1
  fi
}
for prm in tensairity_scene chambers_liquid_gas_mpi; do
  for mode in threads ranks; do
    for k in 1 2; do
      [ "$k" = 2 ] && start_load
      if [ "$mode" = threads ]; then
        OPENBLAS_NUM_THREADS=2 DEAL_II_NUM_THREADS=2 run "$prm-$mode-$k" "$pneuma"
      else
        run "$prm-$mode-$k" mpirun -np 2 "$pneuma"
      fi
      stop_load
    done
    echo -n "$prm, $mode, run 2 (under load) against run 1: "
    $compare "$prm-$mode-1/out" "$prm-$mode-2/out" || fail=1
  done
done
exit $fail
