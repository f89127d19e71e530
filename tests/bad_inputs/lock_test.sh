#!/usr/bin/env bash
# Two demcal processes on one --out: while a first run holds the directory, a second is refused
# with exit code 2 and a message naming the holder's pid, and writes nothing there.
set -uo pipefail
demcal=$1
files=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/demcal_lock.XXXXXX")
trap 'kill "$first" 2>/dev/null; rm -rf "$work"' EXIT
cp "$files/long_run.json" "$work/long.json"  # a valid scene that runs for a while
"$demcal" simulate "$work/long.json" --out "$work/run" --quiet &
first=$!
for _ in $(seq 100); do
  grep -q "pid $first" "$work/run/.demcal.lock" 2>/dev/null && break
  sleep 0.1
done
grep -q "pid $first" "$work/run/.demcal.lock" || { echo "FAIL: no lock file naming $first"; exit 1; }
before=$(ls -la "$work/run" | md5sum)
"$demcal" simulate "$work/long.json" --out "$work/run" --quiet 2>"$work/second.err"
rc=$?
cat "$work/second.err"
[[ $rc == 2 ]] || { echo "FAIL: second run exit $rc, expected 2"; exit 1; }
grep -q "is in use by another demcal process (pid $first: demcal simulate" "$work/second.err" ||
  { echo "FAIL: message does not name the holder"; exit 1; }
"$demcal" experiment aor "$files/exp_wrong_kind.json" --out "$work/run" --quick 2>"$work/third.err"
rc=$?
cat "$work/third.err"
[[ $rc == 2 ]] && grep -q "in use by another demcal process" "$work/third.err" ||
  { echo "FAIL: experiment on a held --out: exit $rc"; exit 1; }
# The workflows take the same lock: a valid workflow and a valid study are refused too.
"$demcal" reproduce alizadeh2018 --out "$work/run" --quick 2>"$work/fourth.err"
rc=$?
cat "$work/fourth.err"
[[ $rc == 2 ]] && grep -q "in use by another demcal process" "$work/fourth.err" ||
  { echo "FAIL: reproduce on a held --out: exit $rc"; exit 1; }
"$demcal" diagnose "$files/diagnose_study.json" --out "$work/run" --quick 2>"$work/fifth.err"
rc=$?
cat "$work/fifth.err"
[[ $rc == 2 ]] && grep -q "in use by another demcal process" "$work/fifth.err" ||
  { echo "FAIL: diagnose on a held --out: exit $rc"; exit 1; }
kill "$first"
wait "$first" 2>/dev/null
# The kernel dropped the lock with the process: the directory is free again.
"$demcal" simulate "$files/cli_restart_missing.json" --out "$work/run" --quiet ||
  { echo "FAIL: the directory stayed locked after the holder died"; exit 1; }
echo "ok"
