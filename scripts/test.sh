#!/bin/bash
# Builds pneuma and its tests (Release) and runs ctest. Arguments go to
# ctest, e.g. `scripts/test.sh -L quick` or `scripts/test.sh -R v1_hencky`.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/mpi_environment.sh"
"$root/scripts/build.sh"
cd "$root/build"
ctest -j "$(nproc)" --output-on-failure "$@"
