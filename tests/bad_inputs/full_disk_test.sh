#!/usr/bin/env bash
# A journal that cannot be written, as on a full disk: the file size limit (ulimit -f, with
# SIGXFSZ ignored) makes write() fail with EFBIG as a full disk fails with ENOSPC, with no special
# file system. With a limit of 0 bytes the journal header cannot be written (the lock's pid line
# is informative and may fail): calibrate and diagnose must end at once with exit 4 (an output
# that cannot be written), not 2, saying which file could not be written.
set -uo pipefail
demcal=$1
files=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/demcal_full_disk.XXXXXX")
trap 'rm -rf "$work"' EXIT
source "$(dirname "$0")/expect.sh"
# The file size limit holds only demcal's writes; its output goes through expect_exit's pipe.
launch() { (trap '' XFSZ; ulimit -f 0; exec timeout 60 "$demcal" "$@"); }
expect() { expect_exit 4 "$@"; }

expect calibrate_header "$work/calibrate/journal.jsonl: cannot write: File too large" -- \
  calibrate "$files/diagnose_study.json" --out "$work/calibrate" --max-evaluations 1 --quiet
expect diagnose_header "$work/diagnose/journal/base.jsonl: cannot write: File too large" -- \
  diagnose "$files/diagnose_study.json" --out "$work/diagnose" --quick --quiet
exit $fail
