#!/bin/bash
# The whole test suite under a concurrent CPU load (issue "Reliability,
# second round"): one busy loop per core (`while :; do :; done`, the same
# priority as the tests) runs beside `ctest -j2`, and every test is forced
# to run again (the deal.II harness skips a test whose output file is up to
# date). Repeats RUNS times and stops at the first failure.
# Usage: [BUSY=n] scripts/ctest_under_load.sh BUILD_DIR [RUNS] [VAR=value ...]
#   e.g. scripts/ctest_under_load.sh build 5
#        scripts/ctest_under_load.sh build 1 OPENBLAS_CORETYPE=Haswell
#        BUSY=1 scripts/ctest_under_load.sh build 5   (one busy loop only)
set -uo pipefail
build="$(realpath "$1")" runs="${2:-1}"
shift $(( $# >= 2 ? 2 : 1 ))
source "$(dirname "$0")/mpi_environment.sh"
busy=()
trap 'kill ${busy[@]} 2>/dev/null' EXIT
for _ in $(seq "${BUSY:-$(nproc)}"); do (while :; do :; done) & busy+=($!); done
cd "$build"
for run in $(seq "$runs"); do
  find tests -maxdepth 3 \( -name output -o -name diff \) -delete 2>/dev/null
  start=$(date +%s)
  env "$@" ctest -j2 > "ctest_under_load_$run.log" 2>&1
  code=$?
  echo "run $run: exit $code, $(( $(date +%s) - start )) s, $(grep 'tests passed' "ctest_under_load_$run.log")"
  [ $code -eq 0 ] || exit $code
done
