#!/usr/bin/env bash
# A rejected run into an --out that holds an earlier run moves the earlier outputs into
# previous_run/ and leaves only its own rejection (summary.json: invalid_scene; rejected.json for
# experiments), so the folder never looks like a finished run of the wrong input.
set -uo pipefail
demcal=$1
files=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/demcal_rejected.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; ls -R "$work/run"; exit 1; }
"$demcal" simulate "$files/cli_restart_missing.json" --out "$work/run" --quiet || fail "valid run"
[[ -f "$work/run/final_particles.csv" && -f "$work/run/scene.json" ]] || fail "no outputs"
"$demcal" simulate "$files/scene_negative_density.json" --out "$work/run" --quiet
rc=$?
[[ $rc == 2 ]] || fail "rejected run exit $rc"
for f in final_particles.csv scene.json vtk/particles.vtk.series; do
  [[ ! -e "$work/run/$f" ]] || fail "$f still in --out after a rejected run"
  [[ -e "$work/run/previous_run/$f" ]] || fail "$f not kept in previous_run/"
done
grep -q '"termination": "invalid_scene"' "$work/run/summary.json" || fail "summary.json"
grep -q '"earlier_outputs_moved_to": "previous_run/"' "$work/run/summary.json" || fail "marker"
# An experiment refused into a folder with an earlier run's result.json.
mkdir -p "$work/exp" && echo '{"angle_deg": 40}' >"$work/exp/result.json"
"$demcal" experiment aor "$files/exp_window_order.json" --out "$work/exp" --quiet
rc=$?
[[ $rc == 2 ]] || fail "rejected experiment exit $rc"
[[ ! -e "$work/exp/result.json" && -e "$work/exp/previous_run/result.json" ]] ||
  fail "result.json not set aside"
grep -q '"termination": "invalid_input"' "$work/exp/rejected.json" || fail "rejected.json"
echo "ok"
