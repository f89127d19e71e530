#!/usr/bin/env bash
# ctest export.liggghts_runs: `demcal export liggghts examples/aor_bp.json` (quick fidelity, cdt
# with the torque conversion) gives a deck Debian's LIGGGHTS-PUBLIC 3.8 runs: the pour's first
# run is cut to 400 steps and the settle loop to one check, then the run must end with the
# deck's last line and a final dump holding the glued base plus poured grains.
# Usage: liggghts_deck_run_test.sh DEMCAL_BIN REPO_ROOT.  Exit 77 (skipped) without liggghts.
set -euo pipefail
demcal=$1
root=$2
if ! command -v liggghts > /dev/null; then
  echo "SKIP: liggghts is not installed (scripts/install_deps.sh installs Debian's liggghts)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$demcal" export liggghts "$root/examples/aor_bp.json" --fidelity quick \
  --rolling-conversion torque --out "$work/deck"
deck=$work/deck/in.demcal
first_run=$(grep -m1 -n '^run ' "$deck" | cut -d: -f1)
sed -i -e "${first_run}s/^run .*/run 400/" \
  -e 's/^variable check loop .*/variable check loop 1/' "$deck"
(cd "$work/deck" && nice -n 10 liggghts -in in.demcal -log log.liggghts > stdout.txt 2>&1) || {
  tail -20 "$work/deck/stdout.txt"
  echo "FAIL: liggghts stopped with an error"
  exit 1
}
if ! grep -q "demcal export: run finished" "$work/deck/stdout.txt"; then
  echo "FAIL: no finish line"
  exit 1
fi
if grep -q "^ERROR" "$work/deck/stdout.txt"; then echo "FAIL: an ERROR line"; exit 1; fi
fixed=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["fixed_particles"])' \
  "$work/deck/export.json")
atoms=$(sed -n '4p' "$work/deck/post/final.liggghts")
echo "final dump: $atoms atoms ($fixed of them the glued base)"
[[ "$atoms" -gt "$fixed" ]] || { echo "FAIL: nothing was poured"; exit 1; }
echo "PASS"
