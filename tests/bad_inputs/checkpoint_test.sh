#!/usr/bin/env bash
# Hostile checkpoints through the real demcal: a checkpoint written by a short run of
# a valid scene, then damaged or paired with another scene. Each must be refused with exit code
# 2 and "FILE: checkpoint: <the failed check>", never a crash, a hang or a run. Edits behind a
# valid checksum ("reframed": payload length and FNV-1a recomputed by ckpt_edit.py) test the
# state checks behind the envelope. Usage: checkpoint_test.sh DEMCAL FILES_DIR
set -uo pipefail
demcal=$1
files=$2
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d "${TMPDIR:-/tmp}/demcal_ckpt.XXXXXX")
trap 'rm -rf "$work"' EXIT
edit() { python3 "$here/ckpt_edit.py" "$@"; }
scene=$files/checkpoint_base.json
timeout 120 "$demcal" simulate "$scene" --out "$work/base" --checkpoint-every-s 0.005 --quiet ||
  { echo "FAIL: the base run did not complete"; exit 1; }
good=$work/base/checkpoint.bin
fail=0
# expect NAME FRAGMENT CHECKPOINT [SCENE]: refused with exit 2 and the fragment.
expect() {
  local name=$1 fragment=$2 checkpoint=$3 scene_file=${4:-$scene}
  timeout 120 "$demcal" simulate "$scene_file" --out "$work/out_$name" --restart "$checkpoint" \
    --quiet >"$work/$name.log" 2>&1
  local rc=$?
  if [[ $rc != 2 ]] || ! grep -qF -- "$fragment" "$work/$name.log"; then
    echo "FAIL $name: exit $rc, expected 2 with '$fragment':"; cat "$work/$name.log"; fail=1
  else
    echo "ok $name: $(grep -F -- "checkpoint:" "$work/$name.log" | head -1)"
  fi
}
# The checkpoint itself restarts (the control case).
timeout 120 "$demcal" simulate "$scene" --out "$work/restart" --restart "$good" --quiet ||
  { echo "FAIL: a valid checkpoint was refused"; fail=1; }

expect other_scene "checkpoint: written for another scene: initial particles differs" "$good" \
  "$files/checkpoint_other_scene.json"
expect other_dt "checkpoint: written for another time step" "$good" "$files/checkpoint_other_dt.json"
expect other_gravity "another scene: gravity differs" "$good" "$files/checkpoint_other_gravity.json"
{ cat "$good"; head -c 1000 /dev/urandom; } >"$work/appended.bin"
expect appended "checkpoint: 1000 unexpected bytes after the end" "$work/appended.bin"
edit "$good" "$work/nan_time.bin" time nan
expect nan_time_raw "checkpoint: checksum mismatch" "$work/nan_time.bin"
edit "$good" "$work/nan_time_reframed.bin" time nan --reframe
expect nan_time "checkpoint: time nan s is not finite" "$work/nan_time_reframed.bin"
edit "$good" "$work/steps_max.bin" steps 9223372036854775807 --reframe
expect steps_max "checkpoint: step count 9223372036854775807 does not match" "$work/steps_max.bin"
# Physically inconsistent states behind a valid checksum (checkpoint_checks_physics.cc).
edit "$good" "$work/budget_huge.bin" budget 1e308 --reframe
expect budget_huge "checkpoint: energy budget 1e+308 J is" "$work/budget_huge.bin"
edit "$good" "$work/mass_edited.bin" mass 1.5 --reframe
expect mass_edited "mass or inertia edited without the radius?" "$work/mass_edited.bin"
edit "$good" "$work/old_format.bin" old-format
expect old_format "checkpoint: format 'demcal-checkpoint/4' of an older demcal" "$work/old_format.bin"
: >"$work/empty.bin"
expect empty "checkpoint: truncated: 0 bytes" "$work/empty.bin"
expect directory "checkpoint: cannot read the file: it is a directory" "$work"
expect dev_zero "checkpoint: not a regular file" /dev/zero
expect json_instead "checkpoint: not a demcal checkpoint" "$scene"
size=$(stat -c %s "$good")
for cut in 1 31 32 33 40 100 $((size / 3)) $((size / 2)) $((size - 9)) $((size - 1)); do
  head -c "$cut" "$good" >"$work/cut_$cut.bin"
  expect "cut_$cut" "checkpoint: truncated" "$work/cut_$cut.bin"
done
for seed in $(seq 1 12); do
  edit "$good" "$work/flip_$seed.bin" flip 20 "$seed"
  expect "flip20_seed$seed" "checkpoint:" "$work/flip_$seed.bin"
done
for seed in 101 102 103 104; do  # a few flips behind a valid checksum: refused or run, no crash
  edit "$good" "$work/rflip_$seed.bin" flip 3 "$seed" --reframe
  timeout 120 "$demcal" simulate "$scene" --out "$work/rflip_$seed" --restart "$work/rflip_$seed.bin" \
    --quiet >"$work/rflip_$seed.log" 2>&1
  rc=$?
  if ((rc != 0 && rc != 2 && rc != 3)); then
    echo "FAIL rflip_$seed: exit $rc"; cat "$work/rflip_$seed.log"; fail=1
  else
    echo "ok rflip_$seed: exit $rc"
  fi
done
((fail == 0)) && echo "all checkpoint cases refused as expected"
exit $fail
