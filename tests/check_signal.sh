#!/bin/bash
# SIGTERM and SIGINT stop a run cleanly: exit 128 + signal, summary.json
# with that exit code and "interrupted", the last converged state written
# (its .pvtu in solution.pvd), every output finite.
# Usage: check_signal.sh PNEUMA_BINARY SOURCE_DIR [PYTHON]
pneuma="$1" src="$2" python="${3:-/usr/bin/python3}"
fail=0
for sig in TERM INT; do
  dir="run-$sig"
  rm -rf "$dir"
  "$pneuma" "$src/parameter_files/airbeam.prm" --set "Geometry/Global refinements=3" \
    --set "Load stepping/Initial increment=0.01" --set "Load stepping/Maximum increment=0.01" \
    --set "Output/Directory=$dir" --set "Output/Quiet=true" > "$dir.log" 2>&1 &
  pid=$!
  # Wait for three converged steps, then signal.
  for i in $(seq 600); do
    [ -f "$dir/history.csv" ] && [ "$(wc -l < "$dir/history.csv")" -ge 4 ] && break
    sleep 0.1
  done
  kill -s "$sig" "$pid"
  wait "$pid"
  code=$?
  expected=$([ $sig = TERM ] && echo 143 || echo 130)
  steps=$(grep -o '"steps": [0-9]*' "$dir/summary.json" | awk '{print $2}')
  last=$(printf "solution_%04d.pvtu" "$steps")
  if [ "$code" -ne "$expected" ] ||
     ! grep -q "\"exit_code\": $expected" "$dir/summary.json" ||
     ! grep -q '"message": "interrupted by SIG' "$dir/summary.json" ||
     ! grep -q "$last" "$dir/solution.pvd" || [ "$steps" -ge 100 ]; then
    echo "FAIL SIG$sig: exit $code, steps $steps, summary: $(head -c 300 "$dir/summary.json")"
    fail=1
  elif ! "$python" "$src/tests/check_outputs_finite.py" "$dir"; then
    fail=1
  else
    echo "ok   SIG$sig: exit $code after $steps steps, $last written, summary says interrupted"
  fi
done
exit $fail
