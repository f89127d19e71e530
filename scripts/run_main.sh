#!/usr/bin/env bash
# Installs what is missing, builds Release and runs the main job on the bundled default data:
# the calibration of the base powder's rolling friction against its measured angle of repose
# (Alizadeh et al. 2018, Table 1: 40.0 deg), examples/calibrate_bp_rolling.json; outputs go to
# out/calibrate_bp/ (README "Calibration"). Run it again to resume an interrupted calibration.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
status=0
"${BUILD_DIR:-build}/apps/demcal" calibrate examples/calibrate_bp_rolling.json --out out/calibrate_bp || status=$?
echo "outputs in out/calibrate_bp/: result.json, calibrated_params.json, calibrated_params.liggghts, evaluations.csv, calibration.svg, journal.jsonl" >&2
exit "$status"
