#!/usr/bin/env bash
# Runs one case of the hostile-input corpus (cases.txt) through the real demcal binary and checks
# its exit code and message: run_case.sh DEMCAL NAME. Fails on a wrong exit code, a missing
# fragment, a forbidden fragment, a crash (signal) or a run longer than 120 s.
set -uo pipefail
demcal=$1
name=$2
here="$(cd "$(dirname "$0")" && pwd)"
# Field i of this case's line (awk keeps empty fields, which `read` with IFS=tab would merge).
field() { awk -F'\t' -v n="$name" -v i="$1" '$1 == n { print $i }' "$here/cases.txt"; }
code=$(field 3)
[[ -n "$code" ]] || { echo "no case '$name' in cases.txt"; exit 1; }
args=$(field 2)
fragment=$(field 4)
absent=$(field 5)
out=$(mktemp -d "${TMPDIR:-/tmp}/demcal_bad_input.XXXXXX")
trap 'rm -rf "$out"' EXIT
args=${args//\{files\}/$here/files}
args=${args//\{out\}/$out/run}
# shellcheck disable=SC2086  # the arguments are words of the manifest
timeout 120 "$demcal" $args >"$out/stdout" 2>"$out/stderr" </dev/null
rc=$?
message=$(cat "$out/stdout" "$out/stderr")
echo "demcal $args"
echo "exit $rc; output:"
echo "$message"
fail=0
if ((rc == 124)); then echo "FAIL: timed out (120 s)"; fail=1; fi
if ((rc > 128)); then echo "FAIL: killed by signal $((rc - 128))"; fail=1; fi
if [[ "$rc" != "$code" ]]; then echo "FAIL: exit code $rc, expected $code"; fail=1; fi
if [[ "$message" != *"$fragment"* ]]; then echo "FAIL: missing fragment: $fragment"; fail=1; fi
if [[ -n "$absent" && "$message" == *"$absent"* ]]; then
  echo "FAIL: must not contain: $absent"; fail=1
fi
exit $fail
