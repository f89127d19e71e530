#!/usr/bin/env bash
# Times the virtual experiments against their speed targets (one run each, 2 cores):
#   aor-quick   examples/aor_bp.json --quick                      (no target)
#   aor         examples/aor_bp.json at the calibration fidelity   ≤ 60 s wall
#   discharge-quick examples/discharge_bp.json --quick            (no target)
#   discharge   examples/discharge_bp.json                        (no target)
#   seg-quick   examples/segregation_paper.json --quick           ≤ 60 s wall
#   seg-default examples/segregation_paper.json (size ×3)         ≤ 600 s wall
# Builds nothing: give it the demcal binary. Each case runs under /usr/bin/time -v; the table
# gives wall and CPU (user + sys) seconds, the load average before the case and met/missed.
#
#   bench/time_experiments.sh BUILD/apps/demcal [OUT_DIR] [CASE ...]
#   flock /tmp/demcal_bench.lock bench/time_experiments.sh /tmp/b/apps/demcal /tmp/time_exp
#
# CASE: any of the above (default: aor, seg-quick, seg-default, in that order); a case without a
# target reports "-" as its status. Outputs of each
# experiment go to OUT_DIR/<case>/ (result.json etc.), the time -v report to OUT_DIR/<case>.time,
# the table to OUT_DIR/table.md. Exit code 0 when every case ran (met or missed), 1 otherwise.
set -u

if [[ $# -lt 1 || ! -x "$1" ]]; then
  echo "usage: $0 DEMCAL_BINARY [OUT_DIR] [aor|aor-quick|discharge|discharge-quick|seg-quick|seg-default ...]" >&2
  exit 2
fi
demcal=$(realpath "$1")
out=${2:-/tmp/demcal_time_experiments}
shift $(( $# >= 2 ? 2 : 1 ))
cases=("$@")
[[ ${#cases[@]} -eq 0 ]] && cases=(aor seg-quick seg-default)
repo=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"

# case → "target_s|arguments" (one replicate each: the targets are for a single run).
declare -A spec=(
  [aor]="60|aor $repo/examples/aor_bp.json --replicates 1"
  [aor-quick]="-|aor $repo/examples/aor_bp.json --quick --replicates 1"
  [discharge]="-|discharge $repo/examples/discharge_bp.json --replicates 1"
  [discharge-quick]="-|discharge $repo/examples/discharge_bp.json --quick --replicates 1"
  [seg-quick]="60|segregation $repo/examples/segregation_paper.json --quick --replicates 1"
  [seg-default]="600|segregation $repo/examples/segregation_paper.json --replicates 1"
)

# Seconds from time -v's "h:mm:ss" or "m:ss.ss".
to_seconds() { awk -F: '{ s = 0; for (i = 1; i <= NF; ++i) s = s * 60 + $i; print s }' <<<"$1"; }

table="$out/table.md"
{
  echo "$("$demcal" --version 2>/dev/null | head -1), $(nproc) cores, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "| case | wall s | CPU s | target wall s | load before | status |"
  echo "|---|---|---|---|---|---|"
} >"$table"

failed=0
for c in "${cases[@]}"; do
  if [[ -z ${spec[$c]+x} ]]; then
    echo "unknown case '$c'" >&2
    failed=1
    continue
  fi
  target=${spec[$c]%%|*}
  read -r -a args <<<"${spec[$c]#*|}"
  load=$(cut -d' ' -f1 /proc/loadavg)
  echo "== $c: demcal experiment ${args[*]} (load $load)" >&2
  rm -rf "${out:?}/$c"
  /usr/bin/time -v -o "$out/$c.time" "$demcal" experiment "${args[@]}" --out "$out/$c" --quiet \
    >"$out/$c.log" 2>&1
  rc=$?
  wall=$(to_seconds "$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$out/$c.time")")
  user=$(sed -n 's/.*User time (seconds): //p' "$out/$c.time")
  sys=$(sed -n 's/.*System time (seconds): //p' "$out/$c.time")
  cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.1f", u + s }')
  if [[ $rc -ne 0 ]]; then
    status="failed (exit $rc, see $c.log)"
    failed=1
  elif [[ "$target" == - ]]; then
    status=-
  elif awk -v w="$wall" -v t="$target" 'BEGIN { exit !(w <= t) }'; then
    status=met
  else
    status=missed
  fi
  printf '| %s | %.1f | %s | %s | %s | %s |\n' "$c" "$wall" "$cpu" "$target" "$load" "$status" \
    >>"$table"
done
cat "$table"
exit $failed
