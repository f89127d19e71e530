#!/usr/bin/env bash
# compare_liggghts.sh -- side-by-side throughput benchmark: demcal vs LIGGGHTS 3.8.
#
# Case (see bench/README.md): 20,000 spheres (d = 2 mm) settled in a 60 x 60 mm box,
# Hertz + history tangential + EPSD2 rolling friction, dt = 2.4e-5 s; time NSTEPS steps
# of the dense bed on 1 and 2 threads (demcal) / MPI ranks (LIGGGHTS).
#
#   1. installs the Debian `liggghts` package if `liggghts` is not on PATH (needs root or sudo)
#   2. in a temporary work dir, runs the LIGGGHTS settle stage once (bench/liggghts/in.settle)
#   3. alternates LIGGGHTS (mpirun -np N) and demcal (demcal_bench --threads N), REPS times each,
#      for N = 1 and 2
#   4. in the same repetitions, the clump case (3-sphere rods; LIGGGHTS fix multisphere, 1 rank)
#      and demcal's sphere case with JKR adhesion (compare_clumps.sh)
#   5. prints medians (particle-steps/s), 2-thread speed-ups, the clump figures, the JKR cost
#      ratio line "jkr cost ratio demcal (JKR/Hertz-Mindlin, 1 thread): X.XX", and as the
#      SECOND-TO-LAST and LAST lines
#        clump throughput ratio demcal/liggghts (1 thread): X.XX
#        throughput ratio demcal/liggghts (1 thread): X.XX
#      ("n/a" instead of X.XX if the demcal binary is missing or failed).
#
# Environment:
#   REPS=3          repetitions per code and thread count
#   NSTEPS=10000    timed steps per run (QUICK=1 makes the default 2000)
#   QUICK=0         1 = quick test mode: fewer timed steps only (still 20,000 particles,
#                   same settled bed)
#   BUILD_DIR=build demcal build dir, relative to the repo root unless absolute;
#                   the binary used is $BUILD_DIR/bench/demcal_bench
#   DEMCAL_REUSE_BED=1  if demcal_bench supports --bed, pass --bed <workdir>/demcal.bed so
#                   demcal settles once (first run) and later runs load that bed; 0 = settle
#                   in every demcal run (plain "throughput --threads N --steps S")
#   BENCH_NICE=     e.g. -15: give every timed job (both codes alike) priority over other work
#                   on a shared box: it runs in its own session (setsid) whose scheduler
#                   autogroup is set to this nice value (Linux autogroups make a plain "nice"
#                   useless against other sessions), and under "nice -n BENCH_NICE". Negative
#                   values need root. With it set, the pre-run idle wait is skipped.
#   LIGGGHTS_RESTART=  path of a bed.restart from an earlier in.settle run: skip the settle
#                   (development shortcut; a normal run settles afresh)
#   KEEP_WORK=0     1 = keep the temporary work dir (logs) and print its path
#   MPIRUN_EXTRA=   extra arguments for mpirun (e.g. --oversubscribe on a 1-core box)
#   CLUMPS_JKR=1    0 = sphere case only (the clump ratio line then says n/a)
#   JKR_COHESION=1e-3  cohesion number of the JKR runs (demcal_bench --jkr-cohesion)
#   NOISE_MAX=0.25  background-load guard: before each timed run wait (up to IDLE_WAIT=180 s)
#                   until other processes use < NOISE_MAX cores; a run during which others used
#                   >= NOISE_MAX cores on average is repeated (up to MAX_RETRY=2 times) and, if
#                   still noisy, kept but counted in the summary
#
# LIGGGHTS particle-steps/s = atoms * steps / T, T from the last "Loop time of T on P procs"
# line of the bench log (the 200-step warm-up run is excluded); for clumps atoms / 3 bodies.
# Shared functions (load guard, median, mpirun setup): lib_compare.sh.
set -euo pipefail

SCRIPT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO_ROOT=$(cd "$SCRIPT_DIR/.." && pwd)
INPUT_DIR=$SCRIPT_DIR/liggghts

QUICK=${QUICK:-0}
if [[ "$QUICK" == 1 ]]; then
  NSTEPS=${NSTEPS:-2000}
else
  NSTEPS=${NSTEPS:-10000}
fi
REPS=${REPS:-3}
BUILD_DIR=${BUILD_DIR:-build}
[[ "$BUILD_DIR" = /* ]] || BUILD_DIR=$REPO_ROOT/$BUILD_DIR
DEMCAL_BIN=$BUILD_DIR/bench/demcal_bench
KEEP_WORK=${KEEP_WORK:-0}
MPIRUN_EXTRA=${MPIRUN_EXTRA:-}
NOISE_MAX=${NOISE_MAX:-0.25}
IDLE_WAIT=${IDLE_WAIT:-180}
MAX_RETRY=${MAX_RETRY:-2}
BENCH_NICE=${BENCH_NICE:-}
THREAD_COUNTS=(1 2)
EXPECTED_PARTICLES=20000

CLUMPS_JKR=${CLUMPS_JKR:-1}

# shellcheck source=bench/lib_compare.sh
source "$SCRIPT_DIR/lib_compare.sh"
# shellcheck source=bench/compare_clumps.sh
source "$SCRIPT_DIR/compare_clumps.sh"

setup_priority
[[ "$REPS" =~ ^[1-9][0-9]*$ ]]   || die "REPS must be a positive integer (got '$REPS')"
[[ "$NSTEPS" =~ ^[1-9][0-9]*$ ]] || die "NSTEPS must be a positive integer (got '$NSTEPS')"
for f in setup.inc case.inc in.settle in.bench in.clump; do
  [[ -f "$INPUT_DIR/$f" ]] || die "missing input file $INPUT_DIR/$f"
done

# ---------------------------------------------------------------- 1. LIGGGHTS install
setup_liggghts

# ---------------------------------------------------------------- demcal binary
HAVE_DEMCAL=1
DEMCAL_BED_ARGS=()
if [[ ! -x "$DEMCAL_BIN" ]]; then
  HAVE_DEMCAL=0
  log "NOTE: demcal benchmark binary not found at $DEMCAL_BIN"
  log "      (build it, or set BUILD_DIR); skipping the demcal runs, LIGGGHTS figures only."
fi

# ---------------------------------------------------------------- work dir
WORK=$(mktemp -d "${TMPDIR:-/tmp}/demcal-vs-liggghts.XXXXXX")
cleanup() {
  if [[ "$KEEP_WORK" == 1 ]]; then log "work dir kept: $WORK"; else rm -rf "$WORK"; fi
}
trap cleanup EXIT
cp "$INPUT_DIR"/setup.inc "$INPUT_DIR"/case.inc "$INPUT_DIR"/in.settle "$INPUT_DIR"/in.bench \
   "$INPUT_DIR"/in.clump "$WORK"/
cd "$WORK"
if [[ $HAVE_DEMCAL == 1 && "${DEMCAL_REUSE_BED:-1}" == 1 ]] &&
   "$DEMCAL_BIN" throughput --help 2>/dev/null | grep -q -- '--bed'; then
  DEMCAL_BED_ARGS=(--bed "$WORK/demcal.bed")   # first demcal run settles and writes it
fi
detect_demcal_variants

log "host: $(nproc) cores, LIGGGHTS package $LIGGGHTS_VERSION, $(date -u '+%Y-%m-%d %H:%M UTC')"
log "case: $EXPECTED_PARTICLES particles, NSTEPS=$NSTEPS timed steps, REPS=$REPS, QUICK=$QUICK${BENCH_NICE:+, timed jobs at nice $BENCH_NICE}"
log "demcal: $([[ $HAVE_DEMCAL == 1 ]] && echo "$DEMCAL_BIN ${DEMCAL_BED_ARGS[*]}" || echo "(absent)")"
[[ "$CLUMPS_JKR" == 1 ]] && log "extra cases: 3-sphere clumps (demcal --clump: $DEMCAL_CLUMP_OK), JKR at Coh = $JKR_COHESION (demcal --jkr-cohesion: $DEMCAL_JKR_OK)"

# ---------------------------------------------------------------- 2. settle (once)
# No "-screen none" here: LIGGGHTS 3.8 crashes writing to a null screen from insertion fixes.
if [[ -n "${LIGGGHTS_RESTART:-}" ]]; then
  [[ -f "$LIGGGHTS_RESTART" ]] || die "LIGGGHTS_RESTART=$LIGGGHTS_RESTART does not exist"
  cp "$LIGGGHTS_RESTART" bed.restart
  log "LIGGGHTS settle skipped: using $LIGGGHTS_RESTART"
else
  log "LIGGGHTS settle (pour + 16000 steps, 1 rank) ..."
  t0=$(now)
  if ! "${PRIO[@]}" "${MPIRUN[@]}" -np 1 liggghts -in in.settle -log log.settle > settle.screen 2>&1; then
    tail -20 settle.screen >&2
    die "LIGGGHTS settle failed (see above)"
  fi
  t1=$(now)
  [[ -f bed.restart ]] || die "settle finished but wrote no bed.restart"
  settle_atoms=$(awk '/^Loop time of/ { n = $12 } END { print n }' log.settle)
  [[ "$settle_atoms" == "$EXPECTED_PARTICLES" ]] ||
    die "settled bed holds $settle_atoms particles, expected $EXPECTED_PARTICLES (insertion incomplete?)"
  log "settle done in $(elapsed_s "$t0" "$t1") s wall;" \
      "bed top (max sphere-centre z) $(awk '$1 == 16001 { print $5 * 1000 " mm" }' log.settle)"
fi

# ---------------------------------------------------------------- 3. timed runs
declare -A LIG_RATES DEM_RATES      # key = thread count, value = space-separated list
LIG_NEIGHS=""
DEM_NEIGHS=""
DEMCAL_FAILED=0

liggghts_attempt() {   # $1 = try, $2 = ranks, $3 = rep
  local try=$1 np=$2 rep=$3 lg line loop steps atoms
  lg="log.bench.np$np.rep$rep.try$try"
  if ! measured "${PRIO[@]}" "${MPIRUN[@]}" -np "$np" liggghts -in in.bench -var nsteps "$NSTEPS" -log "$lg" \
        -screen none > "$lg.out" 2>&1; then
    tail -20 "$lg.out" "$lg" >&2 || true
    die "LIGGGHTS bench run np=$np rep=$rep failed"
  fi
  # last Loop line = timed run: "Loop time of T on P procs for S steps with A atoms, ..."
  line=$(grep '^Loop time of' "$lg" | tail -1)
  loop=$(awk '{ print $4 }' <<< "$line")
  steps=$(awk '{ print $9 }' <<< "$line")
  atoms=$(awk '{ print $12 }' <<< "$line")
  [[ "$steps" == "$NSTEPS" ]] || die "unexpected Loop line in $lg: $line"
  [[ "$atoms" == "$EXPECTED_PARTICLES" ]] || log "WARNING: $atoms atoms left in run np=$np rep=$rep"
  RATE=$(awk -v a="$atoms" -v s="$steps" -v t="$loop" 'BEGIN { printf "%.6g", a * s / t }')
  log "  liggghts ranks=$np rep=$rep: loop $loop s for $steps steps x $atoms atoms -> $(fmt_m "$RATE") particle-steps/s  [other load $BG_LOAD cores]"
  [[ "$np" != 1 ]] || LIG_NEIGHS=$(awk '/^Ave neighs\/atom/ { v = $4 } END { print v }' "$lg")
}

run_liggghts() {   # $1 = ranks, $2 = rep
  retrying liggghts_attempt "$1" "$2"
  LIG_RATES[$1]="${LIG_RATES[$1]:-} $RATE"
}

run_demcal() {     # $1 = threads, $2 = rep
  [[ $HAVE_DEMCAL == 1 && $DEMCAL_FAILED == 0 ]] || return 0
  if ! retrying demcal_attempt "threads=$1 rep=$2" "t$1.rep$2" --threads "$1" --steps "$NSTEPS" \
       "${DEMCAL_BED_ARGS[@]}"; then
    log "         skipping further demcal runs"
    DEMCAL_FAILED=1; DEMCAL_CLUMP_OK=0; DEMCAL_JKR_OK=0; return 0
  fi
  DEM_RATES[$1]="${DEM_RATES[$1]:-} $RATE"
  DEM_NEIGHS=$(bench_value neighbour_pairs_per_particle "$DEMCAL_OUT")
}

log "timed runs ($REPS reps; codes alternate, first code swaps every rep) ..."
t0=$(now)
for ((rep = 1; rep <= REPS; rep++)); do
  for nt in "${THREAD_COUNTS[@]}"; do
    if (( rep % 2 )); then run_liggghts "$nt" "$rep"; run_demcal "$nt" "$rep"
    else                   run_demcal "$nt" "$rep"; run_liggghts "$nt" "$rep"; fi
  done
  [[ "$CLUMPS_JKR" != 1 ]] || run_clump_and_jkr_rep "$rep"
done
t1=$(now)
log "timed runs done in $(elapsed_s "$t0" "$t1") s wall"

# ---------------------------------------------------------------- 4. summary
declare -A LIG_MED DEM_MED
echo
echo "=== throughput, median of $REPS (20,000 particles, $NSTEPS steps; particle-steps/s) ==="
for nt in "${THREAD_COUNTS[@]}"; do
  # shellcheck disable=SC2086
  LIG_MED[$nt]=$(median ${LIG_RATES[$nt]})
  echo "liggghts ${nt} rank(s):   $(fmt_m "${LIG_MED[$nt]}")   $(format_runs "${LIG_RATES[$nt]}")"
done
DEMCAL_OK=0
if [[ $HAVE_DEMCAL == 1 && $DEMCAL_FAILED == 0 ]]; then
  DEMCAL_OK=1
  for nt in "${THREAD_COUNTS[@]}"; do
    # shellcheck disable=SC2086
    DEM_MED[$nt]=$(median ${DEM_RATES[$nt]})
    echo "demcal   ${nt} thread(s): $(fmt_m "${DEM_MED[$nt]}")   $(format_runs "${DEM_RATES[$nt]}")"
  done
else
  echo "demcal:                (not run: $([[ $HAVE_DEMCAL == 0 ]] && echo "binary $DEMCAL_BIN missing" || echo "run failed"))"
fi
echo "liggghts neighbour pairs per particle (1 rank, half list): ${LIG_NEIGHS:-?}"
[[ -n "$DEM_NEIGHS" ]] && echo "demcal   neighbour pairs per particle: $DEM_NEIGHS"
if (( NOISY_RUNS > 0 )); then
  echo "WARNING: $NOISY_RUNS run(s) kept although other processes used >= $NOISE_MAX cores during them"
  echo "         (see 'other load' per run above; for 1-thread runs that is often other work on"
  echo "         the spare core, which still competes for cache and memory bandwidth)"
fi
if grep -q 'not located in any whitelist' log.bench.np1.rep1.try0; then
  echo "note: LIGGGHTS warns hertz/history/epsd2 is not in its compiled fast-path whitelist"
  echo "      (unoptimised contact kernel, 'up to 20%' slower per LIGGGHTS); figures include that."
fi
CLUMP_RATIO=n/a
[[ "$CLUMPS_JKR" != 1 ]] || print_clump_and_jkr_summary
echo
echo "speed-up 2 vs 1 liggghts: $(ratio "${LIG_MED[2]}" "${LIG_MED[1]}")"
if [[ $DEMCAL_OK == 1 ]]; then
  echo "speed-up 2 vs 1 demcal:   $(ratio "${DEM_MED[2]}" "${DEM_MED[1]}")"
  echo "throughput ratio demcal/liggghts (2 threads): $(ratio "${DEM_MED[2]}" "${LIG_MED[2]}")"
fi
echo "clump throughput ratio demcal/liggghts (1 thread): $CLUMP_RATIO"
if [[ $DEMCAL_OK == 1 ]]; then
  echo "throughput ratio demcal/liggghts (1 thread): $(ratio "${DEM_MED[1]}" "${LIG_MED[1]}")"
else
  echo "throughput ratio demcal/liggghts (1 thread): n/a"
fi
