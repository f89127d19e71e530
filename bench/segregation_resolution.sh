#!/usr/bin/env bash
# Fidelity vs resolution of the segregation indices: runs the ternary heap of
# examples/segregation_paper.json at coarse-graining s (size_scale; stiffness_scale 0.01) for two
# cases, then tabulates and plots the indices against s with their random-mixture noise floor:
#   uncoated   the example as it is (Γ = 0 on every contact)
#   adhesion   excessive adhesion, the paper's case study (section 3.5, Fig. 20): Γ = 0.25 J/m² on
#              every EP contact (EP–EP, EP–BP, EP–TAED; not the Perspex walls), carried to the
#              fidelity at constant Cohesion number like every Γ (docs/experiments.md, Fidelity)
# One `demcal experiment segregation --replicates 1` per (s, case, replicate) in
# OUT/s<s>/<case>/r<r>/, replicate r with base seed 2018 + r (the same seeds for both cases:
# common random numbers). Resumable: a run whose result.json exists is skipped, so a killed sweep
# continues where it stopped. Each run's wall time is in its result.json (runs[0].wall_time_s)
# and in OUT/runs.log. Runs go under `nice -n 15`, JOBS (default 2) at a time.
#
#   bench/segregation_resolution.sh BUILD/apps/demcal OUT_DIR [s:replicates ...]
#   bench/segregation_resolution.sh build/apps/demcal /tmp/segres 5:6 3:3     # the default plan
#   bench/segregation_resolution.sh build/apps/demcal /tmp/segres 5:4 3:2 5:8 3:3   # interleaved
#   JOBS=1 bench/segregation_resolution.sh build/apps/demcal /tmp/segres 2:2
#
# Afterwards (and at any time) bench/segregation_resolution_summary.py OUT_DIR writes
# OUT/segregation_resolution.csv, OUT/segregation_resolution_runs.csv and
# OUT/segregation_resolution.svg from every finished run. Exit code 0 when every run finished.
set -u

if [[ $# -lt 2 || ! -x "$1" ]]; then
  echo "usage: $0 DEMCAL_BINARY OUT_DIR [s:replicates ...]   (default plan: 5:6 3:3)" >&2
  exit 2
fi
demcal=$(realpath "$1")
out=$(realpath -m "$2")
shift 2
plan=("$@")
[[ ${#plan[@]} -eq 0 ]] && plan=(5:6 3:3)
jobs=${JOBS:-2}
repo=$(cd "$(dirname "$0")/.." && pwd)
example="$repo/examples/segregation_paper.json"
mkdir -p "$out"

# The parameter file of one run: fidelity s, seed, and Γ on the EP pairs for "adhesion".
make_params() {  # s case replicate > json
  local gamma=0
  [[ $2 == adhesion ]] && gamma=0.25
  jq --argjson s "$1" --argjson seed "$((2018 + $3))" --argjson g "$gamma" --arg case "$2" '
    .fidelity = {name: ("s" + ($s | tostring)), size_scale: $s, stiffness_scale: 0.01}
    | .seed = $seed | .replicates = 1
    | .description = ("fidelity sweep, case " + $case + ": " + .description)
    | .interactions.pairs |= map(
        if (.materials | index("EP")) and (.materials | index("perspex") | not)
        then .interfacial_energy_J_m2 = $g else . end)' "$example"
}

run_one() {  # s case replicate
  local dir="$out/s$1/$2/r$3"
  [[ -f $dir/result.json ]] && return 0
  mkdir -p "$dir"
  make_params "$1" "$2" "$3" >"$dir/params.json" || return 1
  local start=$SECONDS
  nice -n 15 "$demcal" experiment segregation "$dir/params.json" --out "$dir" --replicates 1 \
    --threads 1 --quiet >"$dir/log.txt" 2>&1
  local rc=$?
  echo "$(date -u '+%F %T') s=$1 case=$2 r=$3 exit=$rc wall_s=$((SECONDS - start))" \
    >>"$out/runs.log"
  return $rc
}
export -f run_one make_params
export out demcal example

# Coarse first, case-interleaved, so an early stop leaves comparable pairs.
# A level may appear twice ("5:4 3:2 5:8": four replicates at s = 5, two at s = 3, then four more
# at s = 5); replicates already planned are not repeated.
declare -A planned=()
tasks=()
for p in "${plan[@]}"; do
  s=${p%%:*}
  n=${p##*:}
  for ((r = ${planned[$s]:-0}; r < n; ++r)); do
    for c in uncoated adhesion; do tasks+=("$s $c $r"); done
  done
  ((n > ${planned[$s]:-0})) && planned[$s]=$n
done
echo "segregation_resolution: ${#tasks[@]} runs (plan ${plan[*]}), $jobs at a time -> $out" >&2
printf '%s\n' "${tasks[@]}" | xargs -P "$jobs" -L 1 bash -c 'run_one "$0" "$1" "$2" ||
  echo "run s=$0 $1 r=$2 failed (see its log.txt)" >&2'
done=$(find "$out" -name result.json | wc -l)
echo "segregation_resolution: $done result.json files in $out" >&2
python3 "$repo/bench/segregation_resolution_summary.py" "$out"
