#!/bin/bash
# Every bundled diagnosis case from an empty folder, one at a time, timed; then the scorecard.
#
#   bash bench/diagnose_cases.sh [OUT_DIR]                 # all 26 cases, --quick --threads 2
#   CASES="crossengine_control diagnose_none" THREADS=1 bash bench/diagnose_cases.sh /tmp/dc
#   DEMCAL=/path/to/demcal bash bench/diagnose_cases.sh    # another build's binary
#   STUDY_DIR=/tmp/heldout/studies CASES="crossengine_control_s300k_cdt_relative" \
#     bash bench/diagnose_cases.sh /tmp/heldout/diag       # studies elsewhere (held-out datasets)
#
# A case whose folder holds `done` is skipped, so a killed run resumes with the next case.
# Each case folder: run/ (the diagnosis, docs/diagnose.md "Outputs"), time.txt (/usr/bin/time -v),
# stdout.txt, stderr.txt. The scorecard (bench/diagnose_scorecard.py) is printed and written to
# OUT_DIR/scorecard.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/diagnose_cases}
demcal=${DEMCAL:-$root/build/apps/demcal}
threads=${THREADS:-2}
study_dir=${STUDY_DIR:-examples/diagnose}   # relative to the repository, or absolute
[ -x "$demcal" ] || { echo "no demcal binary at $demcal (build first, or set DEMCAL)" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "/usr/bin/time is missing (apt-get install time)" >&2; exit 2; }

if [ -z "${CASES:-}" ]; then
  CASES=""
  for suffix in "" _cdt_relative _fit_rolling; do
    for c in control adhesion rolling_low wide_psd rolling_strong wall_friction_high elongated; do
      CASES="$CASES crossengine_${c}${suffix}"
    done
  done
  CASES="$CASES diagnose_none diagnose_adhesion_coating diagnose_rolling_strong diagnose_elongated diagnose_wide_psd"
fi

mkdir -p "$out"
cd "$root"
for c in $CASES; do
  dir=$out/$c
  [ -f "$dir/done" ] && continue
  rm -rf "$dir" && mkdir -p "$dir"
  echo "$c: started $(date -u +%FT%TZ), load $(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out/log.txt" >&2
  rc=0
  /usr/bin/time -v -o "$dir/time.txt" "$demcal" diagnose "$study_dir/$c.json" --out "$dir/run" \
    --quick --threads "$threads" > "$dir/stdout.txt" 2> "$dir/stderr.txt" || rc=$?
  echo "$c: ended $(date -u +%FT%TZ), exit $rc, load $(cut -d' ' -f1 /proc/loadavg)" | tee -a "$out/log.txt" >&2
  touch "$dir/done"
done
python3 "$root/bench/diagnose_scorecard.py" "$out" | tee "$out/scorecard.md"
