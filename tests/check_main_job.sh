#!/bin/bash
# The main job's outputs are finite: runs parameter_files/airbeam.prm (on a
# coarser mesh) with VTU output into the working directory and reads every
# output back with VTK (tests/check_outputs_finite.py).
# Usage: check_main_job.sh PNEUMA_BINARY SOURCE_DIR [PYTHON]
set -u
pneuma="$1" src="$2" python="${3:-/usr/bin/python3}"
rm -rf main-job
"$pneuma" "$src/parameter_files/airbeam.prm" \
  --set "Geometry/Global refinements=3" --set "Output/Directory=main-job" \
  --set "Output/Quiet=true" > main-job.log 2>&1
code=$?
if [ $code -ne 0 ]; then
  echo "FAIL: the main job exited with $code"; cat main-job.log; exit 1
fi
exec "$python" "$src/tests/check_outputs_finite.py" main-job
