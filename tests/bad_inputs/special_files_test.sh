#!/usr/bin/env bash
# Paths that are not what they should be, which the corpus (cases.txt) cannot hold as files:
# a lock file that is a link (to a user's file, or dangling), a FIFO or a directory as the
# measurement table, FIFOs as the journals, the scene and the checkpoint. Each must end at once
# (never hang: every run is under `timeout`) with exit 2 and a message that says what the path
# is, and no file outside --out may change or appear.
set -uo pipefail
demcal=$1
files=$2
root="$(cd "$files/../../.." && pwd)"
work=$(mktemp -d "${TMPDIR:-/tmp}/demcal_special.XXXXXX")
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/expect.sh"
expect() { expect_exit 2 "$@"; }
link_message="is a symbolic link; demcal does not follow links for its lock/journal files"

# A lock file linked to a user's file: refused, the file keeps its bytes.
printf 'years of work\n' >"$work/thesis.tex"
mkdir -p "$work/run_link"
ln -s "$work/thesis.tex" "$work/run_link/.demcal.lock"
expect lock_link "$work/run_link/.demcal.lock $link_message" -- \
  simulate "$files/cli_restart_missing.json" --out "$work/run_link" --quiet
[[ "$(cat "$work/thesis.tex")" == "years of work" ]] ||
  { echo "FAIL [lock_link]: the link's target was changed"; fail=1; }

# A dangling lock link: refused, nothing created where it points (outside --out).
mkdir -p "$work/run_dangling"
ln -s "$work/outside.txt" "$work/run_dangling/.demcal.lock"
expect lock_dangling "$link_message" -- \
  simulate "$files/cli_restart_missing.json" --out "$work/run_dangling" --quiet
[[ ! -e "$work/outside.txt" ]] ||
  { echo "FAIL [lock_dangling]: created $work/outside.txt"; fail=1; }

# The measurement table a FIFO (no writer: a plain read blocks for ever), then a directory.
sed -e "s#\"../../../examples/aor_bp.json\"#\"$root/examples/aor_bp.json\"#" \
    -e 's#"table_duplicate_rows.csv"#"table.csv"#' "$files/table_duplicate_rows.json" \
    >"$work/study.json"
grep -q "$root/examples/aor_bp.json" "$work/study.json" ||
  { echo "FAIL: study not rewritten"; exit 1; }
mkfifo "$work/table.csv"
expect table_fifo \
  "table.csv: cannot read the measurement table: not a regular file but a FIFO" -- \
  calibrate "$work/study.json" --out "$work/run_table_fifo" --max-evaluations 1 --quiet
rm "$work/table.csv"
mkdir "$work/table.csv"
expect table_directory "table.csv: cannot read the measurement table: it is a directory" -- \
  calibrate "$work/study.json" --out "$work/run_table_dir" --max-evaluations 1 --quiet
rmdir "$work/table.csv"

# The calibration journal a FIFO, then a link to a user's file.
sed -i 's#"table.csv"#"'"$root"'/datasets/alizadeh2018/measurements.csv"#' "$work/study.json"
mkdir -p "$work/run_journal_fifo"
mkfifo "$work/run_journal_fifo/journal.jsonl"
expect journal_fifo "journal.jsonl: cannot read the journal: not a regular file but a FIFO" -- \
  calibrate "$work/study.json" --out "$work/run_journal_fifo" --max-evaluations 1 --quiet
mkdir -p "$work/run_journal_link"
ln -s "$work/thesis.tex" "$work/run_journal_link/journal.jsonl"
expect journal_link "journal.jsonl $link_message" -- \
  calibrate "$work/study.json" --out "$work/run_journal_link" --max-evaluations 1 --quiet
[[ "$(cat "$work/thesis.tex")" == "years of work" ]] ||
  { echo "FAIL [journal_link]: the link's target was changed"; fail=1; }

# The stage journal of a workflow a FIFO.
mkdir -p "$work/run_stages_fifo"
mkfifo "$work/run_stages_fifo/stages.jsonl"
expect stages_fifo "stages.jsonl: cannot read the stage journal: not a regular file but a FIFO" -- \
  reproduce alizadeh2018 --out "$work/run_stages_fifo" --quick --quiet

# A FIFO as the scene, and as the checkpoint to restart from.
mkfifo "$work/scene.json" "$work/checkpoint.bin"
expect scene_fifo "scene.json: cannot read the scene file: not a regular file but a FIFO" -- \
  simulate "$work/scene.json" --out "$work/run_scene_fifo" --quiet
expect restart_fifo "not a regular file" -- \
  simulate "$files/cli_restart_missing.json" --out "$work/run_restart_fifo" --quiet \
  --restart "$work/checkpoint.bin"

((fail == 0)) && echo "ok"
exit $fail
