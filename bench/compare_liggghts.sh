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
#   4. prints medians (particle-steps/s), 2-thread speed-ups and, as the LAST line,
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
#   NOISE_MAX=0.25  background-load guard: before each timed run wait (up to IDLE_WAIT=180 s)
#                   until other processes use < NOISE_MAX cores; a run during which others used
#                   >= NOISE_MAX cores on average is repeated (up to MAX_RETRY=2 times) and, if
#                   still noisy, kept but counted in the summary
#
# LIGGGHTS particle-steps/s = atoms * steps / T, T from the last "Loop time of T on P procs"
# line of the bench log (the 200-step warm-up run is excluded).
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

log()  { echo "[compare] $*"; }
die()  { echo "[compare] ERROR: $*" >&2; exit 1; }
now()  { date +%s.%N; }
fmt_m() { awk -v x="$1" 'BEGIN { printf "%.3f M", x / 1e6 }'; }   # 2720000 -> "2.720 M"

# median of the numbers given as arguments (average of the middle two for an even count)
median() {
  printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 }
    END { if (NR == 0) exit 1; if (NR % 2) printf "%.6g\n", a[(NR + 1) / 2];
          else printf "%.6g\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}

PRIO=()
if [[ -n "$BENCH_NICE" ]]; then
  [[ "$BENCH_NICE" =~ ^-?[0-9]+$ ]] || die "BENCH_NICE must be an integer (got '$BENCH_NICE')"
  # shellcheck disable=SC2016
  PRIO=(setsid --wait sh -c 'echo "$0" > /proc/self/autogroup 2>/dev/null; exec "$@"' "$BENCH_NICE"
        nice -n "$BENCH_NICE")
fi
[[ "$REPS" =~ ^[1-9][0-9]*$ ]]   || die "REPS must be a positive integer (got '$REPS')"
[[ "$NSTEPS" =~ ^[1-9][0-9]*$ ]] || die "NSTEPS must be a positive integer (got '$NSTEPS')"
for f in setup.inc case.inc in.settle in.bench; do
  [[ -f "$INPUT_DIR/$f" ]] || die "missing input file $INPUT_DIR/$f"
done

# ---------------------------------------------------------------- 1. LIGGGHTS install
if ! command -v liggghts >/dev/null 2>&1 || ! command -v mpirun >/dev/null 2>&1; then
  log "liggghts/mpirun not found; installing the Debian package 'liggghts' (pulls Open MPI)"
  SUDO=
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null 2>&1 || die "not root and no sudo: install liggghts by hand (apt-get install liggghts)"
    SUDO=sudo
  fi
  export DEBIAN_FRONTEND=noninteractive
  if ! $SUDO apt-get install -y -q liggghts; then
    log "install failed; running apt-get update and retrying"
    $SUDO apt-get update -q
    $SUDO apt-get install -y -q liggghts || die "apt-get install liggghts failed"
  fi
fi
LIGGGHTS_VERSION=$(dpkg-query -W -f='${Version}' liggghts 2>/dev/null || echo unknown)

# Open MPI refuses to run as root without this flag. --bind-to none: by default two
# single-rank jobs both bind to core 0; we never run two at once, but stay unbound anyway
# so LIGGGHTS ranks are scheduled like demcal's threads.
MPIRUN=(mpirun --bind-to none)
[[ $(id -u) -eq 0 ]] && MPIRUN+=(--allow-run-as-root)
# shellcheck disable=SC2206
[[ -n "$MPIRUN_EXTRA" ]] && MPIRUN+=($MPIRUN_EXTRA)

# ---------------------------------------------------------------- demcal binary
HAVE_DEMCAL=1
DEMCAL_EXTRA=()
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
cp "$INPUT_DIR"/setup.inc "$INPUT_DIR"/case.inc "$INPUT_DIR"/in.settle "$INPUT_DIR"/in.bench "$WORK"/
cd "$WORK"
if [[ $HAVE_DEMCAL == 1 && "${DEMCAL_REUSE_BED:-1}" == 1 ]] &&
   "$DEMCAL_BIN" throughput --help 2>/dev/null | grep -q -- '--bed'; then
  DEMCAL_EXTRA=(--bed "$WORK/demcal.bed")   # first demcal run settles and writes it
fi

log "host: $(nproc) cores, LIGGGHTS package $LIGGGHTS_VERSION, $(date -u '+%Y-%m-%d %H:%M UTC')"
log "case: $EXPECTED_PARTICLES particles, NSTEPS=$NSTEPS timed steps, REPS=$REPS, QUICK=$QUICK${BENCH_NICE:+, timed jobs at nice $BENCH_NICE}"
log "demcal: $([[ $HAVE_DEMCAL == 1 ]] && echo "$DEMCAL_BIN ${DEMCAL_EXTRA[*]}" || echo "(absent)")"

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
  log "settle done in $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }') s wall;" \
      "bed top (max sphere-centre z) $(awk '$1 == 16001 { print $5 * 1000 " mm" }' log.settle)"
fi

# ---------------------------------------------------------------- 3. timed runs
declare -A LIG_RATES DEM_RATES      # key = thread count, value = space-separated list
LIG_NEIGHS=""
DEM_NEIGHS=""
DEMCAL_FAILED=0

# --- background-load guard (the box has 2 cores; any other busy process distorts timings)
# Busy CPU-seconds of the whole machine (user+nice+system+irq+softirq+steal) ...
HZ=$(getconf CLK_TCK)
sys_busy_s() { awk -v hz="$HZ" '/^cpu / { printf "%.3f\n", ($2 + $3 + $4 + $7 + $8 + $9) / hz; exit }' /proc/stat; }
# ... and CPU-seconds used so far by this script's finished children, stored in CHILD_CPU.
# Must run in this shell: a forked subshell such as $(...) starts with zeroed child times.
CHILD_CPU=0
children_cpu_s() {
  times > "$WORK/.times"
  CHILD_CPU=$(awk 'NR == 2 { s = 0; for (i = 1; i <= 2; i++) { split($i, p, "m"); s += p[1] * 60 + p[2] }
                           printf "%.3f\n", s }' "$WORK/.times")
}
# Wait (up to IDLE_WAIT s) until other processes use less than NOISE_MAX cores over 2 s.
wait_idle() {
  local waited=0 b0 b1 load
  [[ -z "$BENCH_NICE" ]] || return 0
  while :; do
    b0=$(sys_busy_s); sleep 2; b1=$(sys_busy_s)
    load=$(awk -v a="$b0" -v b="$b1" 'BEGIN { printf "%.2f", (b - a) / 2 }')
    awk -v l="$load" -v m="$NOISE_MAX" 'BEGIN { exit !(l < m) }' && return 0
    if (( waited == 0 )); then log "  machine busy ($load cores in use by others); waiting up to ${IDLE_WAIT}s ..."; fi
    (( waited += 2 ))
    if (( waited >= IDLE_WAIT )); then log "  still busy ($load cores) after ${IDLE_WAIT}s; running anyway"; return 0; fi
  done
}
# run "$@" timed; sets BG_LOAD = mean cores used by OTHER processes during the run
BG_LOAD=0
measured() {
  local b0 c0 t0 b1 c1 t1 rc=0
  b0=$(sys_busy_s); children_cpu_s; c0=$CHILD_CPU; t0=$(now)
  "$@" || rc=$?
  t1=$(now); children_cpu_s; c1=$CHILD_CPU; b1=$(sys_busy_s)
  BG_LOAD=$(awk -v b0="$b0" -v b1="$b1" -v c0="$c0" -v c1="$c1" -v t0="$t0" -v t1="$t1" \
    'BEGIN { if (t1 - t0 < 2) { print 0; exit }   # too short for 10 ms accounting ticks
             x = ((b1 - b0) - (c1 - c0)) / (t1 - t0); if (x < 0) x = 0; printf "%.2f", x }')
  return $rc
}
is_noisy() { awk -v l="$BG_LOAD" -v m="$NOISE_MAX" 'BEGIN { exit !(l >= m) }'; }

run_liggghts() {   # $1 = ranks, $2 = rep
  local np=$1 rep=$2 try lg line loop steps atoms rate
  for ((try = 0; ; try++)); do
    lg="log.bench.np$np.rep$rep.try$try"
    wait_idle
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
    rate=$(awk -v a="$atoms" -v s="$steps" -v t="$loop" 'BEGIN { printf "%.6g", a * s / t }')
    log "  liggghts ranks=$np rep=$rep: loop $loop s for $steps steps x $atoms atoms -> $(fmt_m "$rate") particle-steps/s  [other load $BG_LOAD cores]"
    if is_noisy && (( try < MAX_RETRY )); then log "    noisy run discarded, repeating"; continue; fi
    is_noisy && NOISY_RUNS=$((NOISY_RUNS + 1))
    break
  done
  LIG_RATES[$np]="${LIG_RATES[$np]:-} $rate"
  if [[ "$np" == 1 ]]; then
    LIG_NEIGHS=$(awk '/^Ave neighs\/atom/ { v = $4 } END { print v }' "$lg")
  fi
}

run_demcal() {     # $1 = threads, $2 = rep
  local nt=$1 rep=$2 try out rate
  [[ $HAVE_DEMCAL == 1 && $DEMCAL_FAILED == 0 ]] || return 0
  for ((try = 0; ; try++)); do
    out="demcal.t$nt.rep$rep.try$try.out"
    wait_idle
    if ! measured "${PRIO[@]}" "$DEMCAL_BIN" throughput --threads "$nt" --steps "$NSTEPS" "${DEMCAL_EXTRA[@]}" > "$out" 2>&1; then
      tail -20 "$out" >&2 || true
      log "WARNING: demcal run threads=$nt rep=$rep failed; skipping further demcal runs"
      DEMCAL_FAILED=1; return 0
    fi
    rate=$(awk '/^[[:space:]]*particle_steps_per_s:/ { v = $2 } END { print v }' "$out")
    if [[ -z "$rate" ]]; then
      tail -20 "$out" >&2 || true
      log "WARNING: demcal output has no 'particle_steps_per_s:' line; skipping further demcal runs"
      DEMCAL_FAILED=1; return 0
    fi
    log "  demcal   threads=$nt rep=$rep: $(fmt_m "$rate") particle-steps/s  [other load $BG_LOAD cores]"
    if is_noisy && (( try < MAX_RETRY )); then log "    noisy run discarded, repeating"; continue; fi
    is_noisy && NOISY_RUNS=$((NOISY_RUNS + 1))
    break
  done
  DEM_RATES[$nt]="${DEM_RATES[$nt]:-} $rate"
  DEM_NEIGHS=$(awk '/^[[:space:]]*neighbour_pairs_per_particle:/ { v = $2 } END { print v }' "$out")
}

NOISY_RUNS=0
log "timed runs ($REPS reps; codes alternate, first code swaps every rep) ..."
t0=$(now)
for ((rep = 1; rep <= REPS; rep++)); do
  for nt in "${THREAD_COUNTS[@]}"; do
    if (( rep % 2 )); then run_liggghts "$nt" "$rep"; run_demcal "$nt" "$rep"
    else                   run_demcal "$nt" "$rep"; run_liggghts "$nt" "$rep"; fi
  done
done
t1=$(now)
log "timed runs done in $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }') s wall"

# ---------------------------------------------------------------- 4. summary
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
declare -A LIG_MED DEM_MED
echo
echo "=== throughput, median of $REPS (20,000 particles, $NSTEPS steps; particle-steps/s) ==="
for nt in "${THREAD_COUNTS[@]}"; do
  # shellcheck disable=SC2086
  LIG_MED[$nt]=$(median ${LIG_RATES[$nt]})
  echo "liggghts ${nt} rank(s):   $(fmt_m "${LIG_MED[$nt]}")   (runs:$(for r in ${LIG_RATES[$nt]}; do printf ' %s' "$(fmt_m "$r")"; done))"
done
DEMCAL_OK=0
if [[ $HAVE_DEMCAL == 1 && $DEMCAL_FAILED == 0 ]]; then
  DEMCAL_OK=1
  for nt in "${THREAD_COUNTS[@]}"; do
    # shellcheck disable=SC2086
    DEM_MED[$nt]=$(median ${DEM_RATES[$nt]})
    echo "demcal   ${nt} thread(s): $(fmt_m "${DEM_MED[$nt]}")   (runs:$(for r in ${DEM_RATES[$nt]}; do printf ' %s' "$(fmt_m "$r")"; done))"
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
echo "speed-up 2 vs 1 liggghts: $(ratio "${LIG_MED[2]}" "${LIG_MED[1]}")"
if [[ $DEMCAL_OK == 1 ]]; then
  echo "speed-up 2 vs 1 demcal:   $(ratio "${DEM_MED[2]}" "${DEM_MED[1]}")"
  echo "throughput ratio demcal/liggghts (2 threads): $(ratio "${DEM_MED[2]}" "${LIG_MED[2]}")"
  echo "throughput ratio demcal/liggghts (1 thread): $(ratio "${DEM_MED[1]}" "${LIG_MED[1]}")"
else
  echo "throughput ratio demcal/liggghts (1 thread): n/a"
fi
