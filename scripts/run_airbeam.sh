#!/bin/bash
# The main job: builds pneuma if needed and runs the airbeam scene,
# parameter_files/airbeam.prm. Extra arguments go to pneuma
# (e.g. --set "Loads/Pressure/Function expression=2e5").
# Results: output/airbeam/ (solution.pvd, history.csv, summary.json).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root"
exec "$root/build/pneuma" parameter_files/airbeam.prm "$@"
