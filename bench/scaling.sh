#!/usr/bin/env bash
# scaling.sh -- strong scaling of one simulation: demcal on 1, 2, 4, 8, 16 TBB threads against
# LIGGGHTS 3.8 on as many MPI ranks (counts above the cores present are left out), on two cases
# at each size of SIZES (bench/bench_cases.h sizes both from the sphere count):
#   bed   the dense bed of compare_liggghts.sh (d 2 mm, Hertz + history + epsd2, dt 2.4e-5 s):
#         settled SETTLE_STEPS steps (untimed, both codes from the same loose pack), WARMUP
#         steps, then NSTEPS timed steps; particle-steps/s = spheres x NSTEPS / s
#   pour  a column of spheres (d 1.8-2.2 mm) filled just above a frozen rough base and thrown
#         down at 1.5 m/s; NSTEPS timed from the start: the particles crowd where the column
#         lands, so equal chunks of particles are unequal work; moving-sphere-steps/s
# Both codes start from the particles demcal placed (demcal_bench --liggghts-inputs writes the
# LIGGGHTS data file), so the two sides run the same case at any size.
#
# Prints, per case, size and count, one line
#   bed 200000 spheres, 4 threads/ranks: demcal X M, liggghts Y M particle-steps/s; ratio demcal/liggghts R
#   (and below it the same per CPU second: the rate over the cores the job held on average)
# then per case and size
#   strong scaling speed-up demcal (N threads): X  [bed, 200000 spheres]
#   strong scaling speed-up liggghts (N ranks): X  [bed, 200000 spheres]
#   demcal final state identical across thread counts: yes|NO  [bed, 200000 spheres]
#
# Environment:
#   SIZES="20000 200000"   sphere counts
#   CASES="bed pour"
#   COUNTS="1 2 4 8 16"    threads / ranks (capped at nproc unless OVERSUBSCRIBE=1)
#   NSTEPS=4000  WARMUP=200  SETTLE_STEPS=16000   (reduce all three for a quick look)
#   REPS=1                 runs per code and count (median)
#   CODES="demcal liggghts"
#   BASELINE_BIN=          another demcal_bench (e.g. a build of the previous commit): run
#                          after demcal in every repetition on the same bed and counts, so the
#                          machine's load hits both alike; adds "demcal before" to each line,
#                          "speed-up demcal after/before" lines, and whether both builds end in
#                          the same state_digest (a change meant to keep the results exactly)
#   BED_DIR=               settled demcal beds to time instead of settling: BED_DIR/bed.N (a
#                          checkpoint of "demcal_bench throughput --particles N --bed FILE") is
#                          loaded by demcal and handed to LIGGGHTS as its data file (contact
#                          histories start afresh in its warm-up); sizes without one settle
#   BUILD_DIR=build  KEEP_WORK=0  MPIRUN_EXTRA=  BENCH_NICE=   as compare_liggghts.sh
set -euo pipefail

SCRIPT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO_ROOT=$(cd "$SCRIPT_DIR/.." && pwd)
SIZES=${SIZES:-20000 200000}
CASES=${CASES:-bed pour}
COUNTS=${COUNTS:-1 2 4 8 16}
NSTEPS=${NSTEPS:-4000}
WARMUP=${WARMUP:-200}
SETTLE_STEPS=${SETTLE_STEPS:-16000}
REPS=${REPS:-1}
CODES=${CODES:-demcal liggghts}
OVERSUBSCRIBE=${OVERSUBSCRIBE:-0}
BUILD_DIR=${BUILD_DIR:-build}
[[ "$BUILD_DIR" = /* ]] || BUILD_DIR=$REPO_ROOT/$BUILD_DIR
DEMCAL_BIN=$BUILD_DIR/bench/demcal_bench
BASELINE_BIN=${BASELINE_BIN:-}
BED_DIR=${BED_DIR:-}
KEEP_WORK=${KEEP_WORK:-0}
BENCH_NICE=${BENCH_NICE:-}
# shellcheck disable=SC2034  # read by lib_compare.sh
NOISE_MAX=100   # report the other load, never wait for an idle machine (lib_compare.sh)
# shellcheck disable=SC2034
IDLE_WAIT=0
# shellcheck disable=SC2034
MAX_RETRY=0

# shellcheck source=bench/lib_compare.sh
source "$SCRIPT_DIR/lib_compare.sh"
setup_priority
for v in NSTEPS WARMUP SETTLE_STEPS REPS; do
  [[ "${!v}" =~ ^[0-9]+$ ]] || die "$v must be a non-negative integer (got '${!v}')"
done
(( NSTEPS > 0 && REPS > 0 )) || die "NSTEPS and REPS must be positive"
for n in $SIZES; do [[ "$n" =~ ^[1-9][0-9]*$ ]] || die "SIZES: '$n' is not a sphere count"; done
for c in $CASES; do [[ "$c" == bed || "$c" == pour ]] || die "CASES: '$c' (allowed: bed pour)"; done
USE_DEMCAL=0; USE_LIGGGHTS=0
for c in $CODES; do
  case $c in demcal) USE_DEMCAL=1 ;; liggghts) USE_LIGGGHTS=1 ;;
    *) die "CODES: '$c' (allowed: demcal liggghts)" ;; esac
done
[[ -x "$DEMCAL_BIN" ]] || die "$DEMCAL_BIN not found: build demcal_bench (it also writes the LIGGGHTS inputs)"
[[ -z "$BASELINE_BIN" || -x "$BASELINE_BIN" ]] || die "BASELINE_BIN: '$BASELINE_BIN' is not an executable"
(( USE_DEMCAL )) || [[ -z "$BASELINE_BIN" ]] || die "BASELINE_BIN needs demcal in CODES"
(( USE_LIGGGHTS == 0 )) || setup_liggghts
if (( USE_LIGGGHTS )) && [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
CORES=$(nproc)
RUN_COUNTS=()
for t in $COUNTS; do
  [[ "$t" =~ ^[1-9][0-9]*$ ]] || die "COUNTS: '$t' is not a thread count"
  if (( t <= CORES || OVERSUBSCRIBE == 1 )); then RUN_COUNTS+=("$t"); fi
done
(( ${#RUN_COUNTS[@]} > 0 )) || die "no count of COUNTS fits $CORES cores"
MAX_COUNT=${RUN_COUNTS[-1]}

WORK=$(mktemp -d "${TMPDIR:-/tmp}/demcal-scaling.XXXXXX")
cleanup() { if [[ "$KEEP_WORK" == 1 ]]; then log "work dir kept: $WORK"; else rm -rf "$WORK"; fi; }
trap cleanup EXIT
log "host: $CORES cores, $(date -u '+%Y-%m-%d %H:%M UTC'); counts ${RUN_COUNTS[*]}; sizes $SIZES;" \
    "cases $CASES; NSTEPS=$NSTEPS WARMUP=$WARMUP SETTLE_STEPS=$SETTLE_STEPS REPS=$REPS"

# RATE per CPU second of the last measured run (RUN_CORES: the cores it held on average, set-up
# included): on a shared machine a job's wall rate follows the share of the cores it got, its
# rate per CPU second much less (MPI ranks that busy-wait for a descheduled partner still count).
per_cpu() { awk -v r="$1" -v c="$RUN_CORES" 'BEGIN { if (c > 0) printf "%.6g", r / c; else print r }'; }

# "-var NAME VALUE" arguments from a case.vars file into the array VARS.
read_vars() { VARS=(); local k v; while read -r k v; do VARS+=(-var "$k" "$v"); done < "$1"; }

# liggghts_rate LOG MOVING: MOVING x steps / T of the log's last "Loop time of T ... S steps".
liggghts_rate() {
  awk -v m="$2" '/^Loop time of/ { t = $4; s = $9 } END { if (t > 0) printf "%.6g", m * s / t }' "$1"
}

run_liggghts() {  # $1 case dir, $2 deck, $3 ranks, $4 moving spheres, $5 tag; sets RATE
  local dir=$1 deck=$2 np=$3 moving=$4 tag=$5
  read_vars "$dir/case.vars"
  local rc=0
  cd "$dir"   # not a subshell: measured sets BG_LOAD here
  measured "${PRIO[@]}" "${MPIRUN[@]}" -np "$np" liggghts -in "$deck" "${VARS[@]}" \
    -var nsteps "$NSTEPS" -var warmup "$WARMUP" -log "log.$tag" -screen none > "out.$tag" 2>&1 || rc=$?
  cd "$WORK"
  (( rc == 0 )) || { tail -20 "$dir/out.$tag" "$dir/log.$tag" >&2 || true; die "LIGGGHTS $tag failed"; }
  RATE=$(liggghts_rate "$dir/log.$tag" "$moving")
  [[ -n "$RATE" ]] || die "no Loop line in $dir/log.$tag"
}

run_demcal() {  # $1 binary, $2 out file, then demcal_bench arguments; sets RATE and DIGEST
  local bin=$1 out=$2; shift 2
  measured "${PRIO[@]}" "$bin" "$@" > "$out" 2>&1 ||
    { tail -20 "$out" >&2; die "demcal_bench $* failed"; }
  RATE=$(bench_value particle_steps_per_s "$out")
  DIGEST=$(bench_value state_digest "$out")
  [[ -n "$RATE" ]] || die "no particle_steps_per_s in $out"
}

# prepare CASE N DIR: the LIGGGHTS inputs (and for the bed the settled LIGGGHTS restart); sets
# DEMCAL_ARGS (the case's demcal_bench arguments less --threads), DECK and MOVING.
prepare() {
  local case=$1 n=$2 dir=$3
  mkdir -p "$dir"
  if [[ $case == bed ]]; then
    local settle=$SETTLE_STEPS
    if [[ -n "$BED_DIR" && -f "$BED_DIR/bed.$n" ]]; then
      cp "$BED_DIR/bed.$n" "$dir/demcal.bed"   # loaded, never settled (nor rewritten)
      settle=0
      log "  settled bed $BED_DIR/bed.$n: both codes time it (LIGGGHTS converts it, 0 steps)"
    fi
    "$DEMCAL_BIN" throughput --particles "$n" --bed "$dir/demcal.bed" --liggghts-inputs "$dir" > /dev/null
    cp "$SCRIPT_DIR"/liggghts/{setup.inc,case.inc,in.settle_data,in.bench} "$dir"/
    local bed_args=(throughput --particles "$n" --settle-steps "$SETTLE_STEPS" --bed "$dir/demcal.bed")
    DEMCAL_ARGS=("${bed_args[@]}" --steps "$NSTEPS" --warmup-steps "$WARMUP")
    DECK=in.bench
    if (( USE_LIGGGHTS )); then
      read_vars "$dir/case.vars"
      log "  LIGGGHTS settle of the $n-sphere bed ($settle steps, $MAX_COUNT ranks, untimed) ..."
      (cd "$dir" && "${PRIO[@]}" "${MPIRUN[@]}" -np "$MAX_COUNT" liggghts -in in.settle_data \
         "${VARS[@]}" -var settle_steps "$settle" -log log.settle > out.settle 2>&1) ||
        { tail -20 "$dir/out.settle" >&2; die "LIGGGHTS settle failed"; }
    fi
    if (( USE_DEMCAL )) && [[ ! -f "$dir/demcal.bed" ]]; then
      log "  demcal settle of the $n-sphere bed ($SETTLE_STEPS steps, all cores, untimed) ..."
      "$DEMCAL_BIN" "${bed_args[@]}" --threads "$MAX_COUNT" --steps 1 --warmup-steps 0 \
        > "$dir/demcal.settle.out" 2>&1 || { tail -20 "$dir/demcal.settle.out" >&2; die "demcal settle failed"; }
    fi
  else
    "$DEMCAL_BIN" pour --particles "$n" --liggghts-inputs "$dir"
    cp "$SCRIPT_DIR"/liggghts/{setup.inc,in.pour_data} "$SCRIPT_DIR"/pours/material.inc "$dir"/
    DEMCAL_ARGS=(pour --particles "$n" --steps "$NSTEPS")
    DECK=in.pour_data
  fi
  MOVING=$n
}

SUMMARY=()
for n in $SIZES; do
  for case in $CASES; do
    dir="$WORK/$case.$n"
    log "$case, $n spheres:"
    prepare "$case" "$n" "$dir"
    declare -A DEM=() LIG=() DIG=() BASE=() BASE_DIG=() DEM_C=() LIG_C=() BASE_C=()
    for t in "${RUN_COUNTS[@]}"; do
      dem_runs=() lig_runs=() base_runs=() dem_cpu=() lig_cpu=() base_cpu=()
      for ((rep = 1; rep <= REPS; rep++)); do
        if (( USE_DEMCAL )); then
          run_demcal "$DEMCAL_BIN" "$dir/demcal.t$t.rep$rep.out" "${DEMCAL_ARGS[@]}" --threads "$t"
          dem_runs+=("$RATE"); DIG[$t]=$DIGEST; dem_cpu+=("$(per_cpu "$RATE")")
          log "    demcal   $t thread(s) rep $rep: $(fmt_m "$RATE"), $(fmt_m "${dem_cpu[-1]}") per CPU s  [held $RUN_CORES cores; other load $BG_LOAD cores]"
        fi
        if [[ -n "$BASELINE_BIN" ]]; then
          run_demcal "$BASELINE_BIN" "$dir/before.t$t.rep$rep.out" "${DEMCAL_ARGS[@]}" --threads "$t"
          base_runs+=("$RATE"); BASE_DIG[$t]=$DIGEST; base_cpu+=("$(per_cpu "$RATE")")
          log "    before   $t thread(s) rep $rep: $(fmt_m "$RATE"), $(fmt_m "${base_cpu[-1]}") per CPU s  [held $RUN_CORES cores; other load $BG_LOAD cores]"
        fi
        if (( USE_LIGGGHTS )); then
          run_liggghts "$dir" "$DECK" "$t" "$MOVING" "np$t.rep$rep"
          lig_runs+=("$RATE"); lig_cpu+=("$(per_cpu "$RATE")")
          log "    liggghts $t rank(s)  rep $rep: $(fmt_m "$RATE"), $(fmt_m "${lig_cpu[-1]}") per CPU s  [held $RUN_CORES cores; other load $BG_LOAD cores]"
        fi
      done
      (( USE_DEMCAL )) && DEM[$t]=$(median "${dem_runs[@]}") && DEM_C[$t]=$(median "${dem_cpu[@]}")
      (( USE_LIGGGHTS )) && LIG[$t]=$(median "${lig_runs[@]}") && LIG_C[$t]=$(median "${lig_cpu[@]}")
      [[ -n "$BASELINE_BIN" ]] && BASE[$t]=$(median "${base_runs[@]}") && BASE_C[$t]=$(median "${base_cpu[@]}")
      line="$case $n spheres, $t threads/ranks:"
      (( USE_DEMCAL )) && line+=" demcal $(fmt_m "${DEM[$t]}")"
      [[ -n "$BASELINE_BIN" ]] && line+=", demcal before $(fmt_m "${BASE[$t]}")"
      (( USE_LIGGGHTS )) && line+="$( (( USE_DEMCAL )) && echo ,) liggghts $(fmt_m "${LIG[$t]}")"
      line+=" particle-steps/s"
      (( USE_DEMCAL && USE_LIGGGHTS )) && line+="; ratio demcal/liggghts $(ratio "${DEM[$t]}" "${LIG[$t]}")"
      [[ -n "$BASELINE_BIN" && USE_LIGGGHTS -eq 1 ]] &&
        line+=" (before: $(ratio "${BASE[$t]}" "${LIG[$t]}"))"
      SUMMARY+=("$line")
      line="  per CPU second ($case $n spheres, $t threads/ranks):"
      (( USE_DEMCAL )) && line+=" demcal $(fmt_m "${DEM_C[$t]}")"
      [[ -n "$BASELINE_BIN" ]] && line+=", demcal before $(fmt_m "${BASE_C[$t]}")"
      (( USE_LIGGGHTS )) && line+=", liggghts $(fmt_m "${LIG_C[$t]}")"
      (( USE_DEMCAL && USE_LIGGGHTS )) && line+="; ratio demcal/liggghts $(ratio "${DEM_C[$t]}" "${LIG_C[$t]}")"
      [[ -n "$BASELINE_BIN" && USE_LIGGGHTS -eq 1 ]] &&
        line+=" (before: $(ratio "${BASE_C[$t]}" "${LIG_C[$t]}"))"
      [[ -n "$BASELINE_BIN" ]] && line+="; after/before $(ratio "${DEM_C[$t]}" "${BASE_C[$t]}")"
      SUMMARY+=("$line")
      if [[ -n "$BASELINE_BIN" ]]; then
        same=$([[ "${BASE_DIG[$t]}" == "${DIG[$t]}" ]] && echo yes || echo NO)
        SUMMARY+=("speed-up demcal after/before ($t threads): $(ratio "${DEM[$t]}" "${BASE[$t]}"); same final state: $same  [$case, $n spheres]")
      fi
    done
    first=${RUN_COUNTS[0]}
    for t in "${RUN_COUNTS[@]:1}"; do
      (( USE_DEMCAL )) &&
        SUMMARY+=("strong scaling speed-up demcal ($t threads): $(ratio "${DEM[$t]}" "${DEM[$first]}")  [$case, $n spheres]")
      (( USE_LIGGGHTS )) &&
        SUMMARY+=("strong scaling speed-up liggghts ($t ranks): $(ratio "${LIG[$t]}" "${LIG[$first]}")  [$case, $n spheres]")
    done
    if (( USE_DEMCAL )); then
      same=yes
      for t in "${RUN_COUNTS[@]}"; do [[ "${DIG[$t]}" == "${DIG[$first]}" ]] || same=NO; done
      SUMMARY+=("demcal final state identical across thread counts: $same  [$case, $n spheres]")
    fi
    unset DEM LIG DIG BASE BASE_DIG DEM_C LIG_C BASE_C
  done
done

echo
echo "=== strong scaling ($CORES cores; NSTEPS=$NSTEPS, median of $REPS) ==="
printf '%s\n' "${SUMMARY[@]}"
