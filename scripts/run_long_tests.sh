#!/usr/bin/env bash
# Installs what is missing, builds Release and runs the long DEM tests that do not fit CI's
# budget (Catch2 tag [long], hidden from ctest by [.]): twin calibrations on the DEM, workflows
# end to end at --quick fidelity. Each test says its expected wall time in a comment.
# Usage: bash scripts/run_long_tests.sh ["[long][calibrate]"]   (a Catch2 tag filter)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
filter=${1:-"[long]"}
"${BUILD_DIR:-build}/tests/demcal_tests" "$filter" --durations yes
# The MPI farm on a diagnosis (tests/objectives/farm/mpi_diagnose_test.sh), where mpirun exists
# and no filter was given.
if [[ -z ${1:-} ]] && command -v mpirun > /dev/null; then
  bash tests/objectives/farm/mpi_diagnose_test.sh "${BUILD_DIR:-build}/apps/demcal" "$PWD"
fi
