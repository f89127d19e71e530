#!/usr/bin/env bash
# Installs what is missing, builds Release and runs the main job on the bundled data: the method of
# Alizadeh et al. 2018 end to end, `demcal reproduce alizadeh2018` at its default fidelity
# (docs/reproduce.md); outputs go to out/reproduce/ (report.html, summary.json, ...). Run it again
# to resume an interrupted run from its stage journal.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
status=0
"${BUILD_DIR:-build}/apps/demcal" reproduce alizadeh2018 --out out/reproduce || status=$?
echo "outputs in out/reproduce/: report.html (open in a browser), report.md, summary.json, params/, stages.jsonl and each stage's folder (docs/reproduce.md)" >&2
exit "$status"
