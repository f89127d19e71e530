#!/usr/bin/env bash
# Installs what is missing, builds Release and runs the main job on the bundled default data.
# Until the calibration issues land, the main job is the demonstration scene: spheres poured
# into a box (examples/pour_box.json); outputs go to out/pour_box/ (see README "Output files").
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
"${BUILD_DIR:-build}/apps/demcal" simulate examples/pour_box.json --out out/pour_box
echo "outputs in out/pour_box/: summary.json, final_particles.csv, scene.json, vtk/particles.vtk.series (open in ParaView)" >&2
