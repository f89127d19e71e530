#!/usr/bin/env bash
# compare_pours.sh -- demcal vs LIGGGHTS 3.8 on the workloads a calibration runs, one
# thread / one MPI rank, both codes from the same inputs (bench/pours/make_cases.py writes the
# demcal scenes and the LIGGGHTS data, STL and variables from one parameter set):
#   heap       15,000 spheres (d 1.8-2.2 mm) poured from a 5 mm-radius stream onto a frozen rough
#              base of 7,393 fixed spheres, until 0.1 s after the last insertion (~113,000 steps)
#   discharge  15,000 spheres filled into a flat-bottomed silo (R 25 mm) with an STL bottom and a
#              16 mm orifice, plugged for 0.4 s, then 1.2 s of discharge (~66,700 steps)
# Each case: demcal simulate SCENE --threads 1 and liggghts -in in.CASE (mpirun -np 1), one after
# the other, REPS times (codes alternate). Wall and CPU (user+sys) seconds of each whole process
# (setup and insertion included, both codes alike) under /usr/bin/time. The ratio is LIGGGHTS CPU
# seconds / demcal CPU seconds for the same simulated steps: on the shared 2-core machine the
# wall time of a single-threaded job follows the other load, its CPU time much less (the wall
# ratio is printed beside it). Prints the medians and, as the LAST two lines:
#   pour throughput ratio demcal/liggghts (1 thread): X.XX
#   discharge throughput ratio demcal/liggghts (1 thread): X.XX
# ("n/a" when a demcal run failed or the binary is missing).
#
#   bench/compare_pours.sh                    # full cases, ~10 min per code and case
#   QUICK=1 bench/compare_pours.sh            # 1,500 / 2,000 spheres: checks the script works
# Environment:
#   BUILD_DIR=build  demcal build dir (relative to the repo root unless absolute); uses
#                    $BUILD_DIR/apps/demcal
#   REPS=1           runs per code and case
#   CASES="heap discharge"
#   KEEP_WORK=0      1 = keep the work dir (inputs, logs, demcal outputs) and print its path
#   MPIRUN_EXTRA=    extra mpirun arguments
# The machine is shared: each run reports the load of OTHER processes during it ("other load",
# cores); compare ratios from one script run only.
set -euo pipefail

SCRIPT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO_ROOT=$(cd "$SCRIPT_DIR/.." && pwd)
INPUT_DIR=$SCRIPT_DIR/pours
QUICK=${QUICK:-0}
REPS=${REPS:-1}
CASES=${CASES:-heap discharge}
BUILD_DIR=${BUILD_DIR:-build}
[[ "$BUILD_DIR" = /* ]] || BUILD_DIR=$REPO_ROOT/$BUILD_DIR
DEMCAL_BIN=$BUILD_DIR/apps/demcal
KEEP_WORK=${KEEP_WORK:-0}
# lib_compare.sh's load guard: report the other load, never wait for an idle machine here
NOISE_MAX=${NOISE_MAX:-100}
IDLE_WAIT=0
MAX_RETRY=0
BENCH_NICE=${BENCH_NICE:-}

# shellcheck source=bench/lib_compare.sh
source "$SCRIPT_DIR/lib_compare.sh"
setup_priority
[[ "$REPS" =~ ^[1-9][0-9]*$ ]] || die "REPS must be a positive integer (got '$REPS')"
for f in make_cases.py material.inc in.heap in.discharge; do
  [[ -f "$INPUT_DIR/$f" ]] || die "missing input file $INPUT_DIR/$f"
done
command -v python3 >/dev/null || die "python3 is needed to write the case inputs"
setup_liggghts
HAVE_DEMCAL=1
[[ -x "$DEMCAL_BIN" ]] || { HAVE_DEMCAL=0; log "NOTE: $DEMCAL_BIN not found: LIGGGHTS only"; }

WORK=$(mktemp -d "${TMPDIR:-/tmp}/demcal-pours.XXXXXX")
cleanup() { if [[ "$KEEP_WORK" == 1 ]]; then log "work dir kept: $WORK"; else rm -rf "$WORK"; fi; }
trap cleanup EXIT
cp "$INPUT_DIR"/material.inc "$INPUT_DIR"/in.heap "$INPUT_DIR"/in.discharge "$WORK"/
cd "$WORK"
python3 "$INPUT_DIR/make_cases.py" "$WORK" $([[ "$QUICK" == 1 ]] && echo --quick) | sed 's/^/[compare] /'
log "host: $(nproc) cores, LIGGGHTS package $LIGGGHTS_VERSION, $(date -u '+%Y-%m-%d %H:%M UTC'), QUICK=$QUICK, REPS=$REPS"
log "demcal: $([[ $HAVE_DEMCAL == 1 ]] && "$DEMCAL_BIN" --version 2>/dev/null | head -1 || echo absent)"

# Runs "$@" under /usr/bin/time; sets WALL and CPU (s).
timed() {
  local tag=$1; shift
  local rc=0
  measured /usr/bin/time -f "%e %U %S" -o "$tag.time" "${PRIO[@]}" "$@" > "$tag.log" 2>&1 || rc=$?
  if [[ $rc != 0 ]]; then tail -20 "$tag.log" >&2 || true; return $rc; fi
  read -r WALL user sys < <(tail -1 "$tag.time")
  CPU=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.1f", u + s }')
}

declare -A LIG_WALL DEM_WALL LIG_CPU DEM_CPU DEM_FAILED
run_liggghts() {  # $1 case, $2 rep
  local vars=()
  while read -r k v; do vars+=(-var "$k" "$v"); done < "$1.vars"
  timed "lig.$1.$2" "${MPIRUN[@]}" -np 1 liggghts -in "in.$1" "${vars[@]}" -log "log.$1.$2" ||
    die "LIGGGHTS $1 run $2 failed (log: $WORK/lig.$1.$2.log)"
  local atoms
  atoms=$(awk '/^Loop time of/ { n = $12 } END { print n }' "log.$1.$2")
  log "  liggghts $1 rep $2: $WALL s wall, $CPU s CPU, $atoms atoms at the end; last run: $(awk '/^(Pair|Neigh|Other) +time/ { v[$1] = $NF } END { gsub(/[()]/, "", v["Pair"]); gsub(/[()]/, "", v["Neigh"]); gsub(/[()]/, "", v["Other"]); printf "pair %.0f %%, neigh %.0f %%, other %.0f %%", v["Pair"], v["Neigh"], v["Other"] }' "log.$1.$2") [other load $BG_LOAD cores]"
  LIG_WALL[$1]="${LIG_WALL[$1]:-} $WALL"; LIG_CPU[$1]="${LIG_CPU[$1]:-} $CPU"
}
run_demcal() {    # $1 case, $2 rep
  [[ $HAVE_DEMCAL == 1 && -z "${DEM_FAILED[$1]:-}" ]] || return 0
  if ! timed "dem.$1.$2" "$DEMCAL_BIN" simulate "$1.json" --out "out.$1.$2" --threads 1 --quiet; then
    log "WARNING: demcal $1 run $2 failed (log: $WORK/dem.$1.$2.log)"; DEM_FAILED[$1]=1; return 0
  fi
  local n
  n=$(python3 -c "import json,sys; s=json.load(open(sys.argv[1])); p=s['phase_wall_time_s']; t=sum(p.values()) or 1
print(s['particles'], 'bodies at the end,', s['termination'] + ',', s['neighbour_rebuilds'], 'rebuilds; phases:',
      ', '.join('%s %.0f %%' % (k[:-2], 100 * v / t) for k, v in p.items()))" "out.$1.$2/summary.json")
  log "  demcal   $1 rep $2: $WALL s wall, $CPU s CPU, $n [other load $BG_LOAD cores]"
  DEM_WALL[$1]="${DEM_WALL[$1]:-} $WALL"; DEM_CPU[$1]="${DEM_CPU[$1]:-} $CPU"
}

t0=$(now)
for c in $CASES; do
  [[ -f "$c.json" && -f "$c.vars" ]] || die "unknown case '$c' (heap, discharge)"
  for ((rep = 1; rep <= REPS; rep++)); do
    if (( rep % 2 )); then run_liggghts "$c" "$rep"; run_demcal "$c" "$rep"
    else                   run_demcal "$c" "$rep"; run_liggghts "$c" "$rep"; fi
  done
done
log "all runs done in $(elapsed_s "$t0" "$(now)") s wall"

echo
echo "=== pours, 1 thread, median of $REPS (wall / CPU seconds of each whole run) ==="
declare -A RATIO
for c in $CASES; do
  # shellcheck disable=SC2086
  lw=$(median ${LIG_WALL[$c]}); lc=$(median ${LIG_CPU[$c]})
  echo "$c: liggghts ${lw} s wall, ${lc} s CPU"
  RATIO[$c]=n/a
  if [[ $HAVE_DEMCAL == 1 && -z "${DEM_FAILED[$c]:-}" ]]; then
    # shellcheck disable=SC2086
    dw=$(median ${DEM_WALL[$c]}); dc=$(median ${DEM_CPU[$c]})
    echo "$c: demcal   ${dw} s wall, ${dc} s CPU (wall ratio liggghts/demcal $(ratio "$lw" "$dw"))"
    RATIO[$c]=$(ratio "$lc" "$dc")
  fi
done
echo "note: LIGGGHTS warns hertz/history/epsd2 is not in its compiled fast-path whitelist (figures include that)"
echo "pour throughput ratio demcal/liggghts (1 thread): ${RATIO[heap]:-n/a}"
echo "discharge throughput ratio demcal/liggghts (1 thread): ${RATIO[discharge]:-n/a}"
