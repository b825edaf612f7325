#!/bin/bash
# Checkpoint and restart: a run stopped after step k (Checkpoint/Stop after
# step, or SIGTERM) and continued with --restart ends with the same
# summary.json as the uninterrupted run (every number to 1e-10 relative,
# the scale of a vector component being the vector's largest), on 1 and 2
# ranks and across rank counts; the restarted run's solution.pvd lists every
# step once, as the uninterrupted run's does. The checkpoint keeps the last
# step's increment, so the restarted step starts from the same predictor
# (the load-step extrapolation; the secant of an arc-length stage). The
# square airbag stops after its relaxed first stage and restarts into the
# static one (the relaxation's counts come back with the checkpoint). The
# vibrating membrane stops in its explicit stage and continues with the
# checkpoint's velocity, step and energies. The dragged sheet stops while
# it slides and continues with the checkpoint's friction anchors.
# Usage: check_restart.sh PNEUMA_BINARY SOURCE_DIR [PYTHON]
pneuma="$1" src="$2" python="${3:-/usr/bin/python3}"
compare="$python $src/tests/compare_summaries.py"
fail=0
run() { # ranks, parameter file, directory, extra arguments...
  local n="$1" prm="$2" dir="$3"
  shift 3
  if [ "$n" -eq 1 ]; then
    "$pneuma" "$prm" --set "Output/Directory=$dir" --set "Output/Quiet=true" "$@"
  else
    mpirun -np "$n" "$pneuma" "$prm" --set "Output/Directory=$dir" \
      --set "Output/Quiet=true" "$@"
  fi > "$dir.log" 2>&1
}
same_series() { # reference directory, restarted directory
  if [ -f "$1/solution.pvd" ] &&
     ! diff <(grep -o 'timestep="[^"]*"[^>]*file="[^"]*"' "$1/solution.pvd") \
            <(grep -o 'timestep="[^"]*"[^>]*file="[^"]*"' "$2/solution.pvd") > /dev/null; then
    echo "FAIL $2/solution.pvd differs from $1/solution.pvd"
    return 1
  fi
}
# Shipped files name their meshes relative to the project's root.
ln -sfn "$src/meshes" meshes
# name, ranks of the first part, ranks of the restart, stop step, file
for case in \
  "square_airbag 2 2 1 $src/parameter_files/square_airbag.prm" \
  "tensairity 1 1 2 $src/tests/tensairity_scene.prm" \
  "liquid_gas 1 1 3 $src/tests/chambers_liquid_gas_mpi.prm" \
  "liquid_gas 2 2 3 $src/tests/chambers_liquid_gas_mpi.prm" \
  "liquid_gas 2 1 5 $src/tests/chambers_liquid_gas_mpi.prm" \
  "contact_patch 2 2 1 $src/tests/contact_patch_mpi.prm" \
  "sphere_arc_length 1 1 6 $src/parameter_files/sphere_arc_length.prm" \
  "membrane_vibration 1 1 50 $src/parameter_files/membrane_vibration.prm" \
  "membrane_vibration 2 2 50 $src/parameter_files/membrane_vibration.prm" \
  "sheet_dragged 1 1 6 $src/parameter_files/sheet_dragged.prm" \
  "sheet_dragged 2 1 6 $src/parameter_files/sheet_dragged.prm" \
  "tube_pressed_by_force 1 1 14 $src/parameter_files/tube_pressed_by_force.prm"; do
  set -- $case
  name="$1" first="$2" second="$3" stop="$4" prm="$5"
  full="$name-$first-full" part="$name-$first-$second-restart"
  rm -rf "$full" "$part"
  run "$first" "$prm" "$full" || { echo "FAIL $full: exit $?"; fail=1; continue; }
  run "$first" "$prm" "$part" --set "Checkpoint/Stop after step=$stop"
  code=$?
  if [ $code -ne 0 ] || ! grep -q "stopped after step $stop" "$part.log"; then
    echo "FAIL $part: the stop after step $stop gave exit $code: $(cat "$part.log")"
    fail=1; continue
  fi
  run "$second" "$prm" "$part" --restart "$part/checkpoint"
  code=$?
  if [ $code -ne 0 ]; then
    echo "FAIL $part: the restart gave exit $code: $(cat "$part.log")"
    fail=1; continue
  fi
  echo -n "$name, stop after step $stop on $first rank(s), restart on $second: "
  $compare "$full/summary.json" "$part/summary.json" || fail=1
  same_series "$full" "$part" || fail=1
done

# Periodic checkpoints (by steps, by minutes): the last one of a complete
# run is at its final step; a restart from it has nothing left to do and
# reports the same final state (the chamber reports of a restored state).
prm="$src/tests/chambers_liquid_gas_mpi.prm"
for every in "Interval steps=4" "Interval minutes=1e-9"; do
  dir="periodic-${every%%=*}"; dir="${dir// /_}"
  rm -rf "$dir" "$dir-again"
  run 1 "$prm" "$dir" --set "Checkpoint/$every" || { echo "FAIL $dir: exit $?"; fail=1; continue; }
  run 1 "$prm" "$dir-again" --restart "$dir/checkpoint"
  code=$?
  echo -n "liquid_gas, Checkpoint/$every, restart at the end: exit $code, "
  $compare liquid_gas-1-full/summary.json "$dir-again/summary.json" || fail=1
  [ $code -eq 0 ] || fail=1
done

# A run stopped by SIGTERM leaves a checkpoint; the restart completes it.
prm="$src/parameter_files/airbeam.prm"
args=(--set "Geometry/Global refinements=3" --set "Load stepping/Initial increment=0.02"
      --set "Load stepping/Maximum increment=0.02")
rm -rf airbeam-full airbeam-signal
run 1 "$prm" airbeam-full "${args[@]}" || { echo "FAIL airbeam-full: exit $?"; fail=1; }
"$pneuma" "$prm" "${args[@]}" --set "Output/Directory=airbeam-signal" \
  --set "Output/Quiet=true" > airbeam-signal.log 2>&1 &
pid=$!
# Until it has converged three steps (however loaded the machine: no time
# limit but the test's), or ended.
while kill -0 "$pid" 2> /dev/null; do
  [ -f airbeam-signal/history.csv ] && [ "$(wc -l < airbeam-signal/history.csv)" -ge 4 ] && break
  sleep 0.1
done
kill -s TERM "$pid"
wait "$pid"
code=$?
if [ $code -ne 143 ] || [ ! -f airbeam-signal/checkpoint/state.bin ]; then
  echo "FAIL SIGTERM: exit $code, no checkpoint: $(cat airbeam-signal.log)"
  fail=1
else
  steps=$(grep -o '"steps": [0-9]*' airbeam-signal/summary.json | awk '{print $2}')
  run 1 "$prm" airbeam-signal "${args[@]}" --restart airbeam-signal/checkpoint
  code=$?
  echo -n "airbeam, SIGTERM after step $steps, restart: exit $code, "
  $compare airbeam-full/summary.json airbeam-signal/summary.json || fail=1
  same_series airbeam-full airbeam-signal || fail=1
  [ $code -eq 0 ] || fail=1
fi
"$python" "$src/tests/check_outputs_finite.py" airbeam-signal || fail=1
exit $fail
