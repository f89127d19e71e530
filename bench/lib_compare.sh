# shellcheck shell=bash
# lib_compare.sh -- shell functions shared by the demcal vs LIGGGHTS benchmark scripts
# (sourced by compare_liggghts.sh; not executable on its own). Expects: set -euo pipefail,
# and the variables WORK, NOISE_MAX, IDLE_WAIT, MAX_RETRY, BENCH_NICE set by the caller.
# Provides: log/die helpers, number formatting, median, the LIGGGHTS install and mpirun command
# (MPIRUN), the priority prefix (PRIO), and the background-load guard used by every timed run
# (retrying / measured / BG_LOAD / RUN_CORES / NOISY_RUNS).

log()  { echo "[compare] $*"; }
die()  { echo "[compare] ERROR: $*" >&2; exit 1; }
now()  { date +%s.%N; }
fmt_m() { awk -v x="$1" 'BEGIN { printf "%.3f M", x / 1e6 }'; }   # 2720000 -> "2.720 M"
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
elapsed_s() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

# median of the numbers given as arguments (average of the middle two for an even count)
median() {
  printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 }
    END { if (NR == 0) exit 1; if (NR % 2) printf "%.6g\n", a[(NR + 1) / 2];
          else printf "%.6g\n", (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}

# "  (runs: 1.234 M 1.250 M)" for a space-separated list of rates
format_runs() { local r; printf '(runs:'; for r in $1; do printf ' %s' "$(fmt_m "$r")"; done; printf ')'; }

# PRIO: command prefix that runs a timed job at priority BENCH_NICE in its own session, whose
# scheduler autogroup gets that nice value (Linux autogroups make a plain "nice" useless against
# other sessions). Empty when BENCH_NICE is unset.
setup_priority() {
  PRIO=()
  [[ -n "$BENCH_NICE" ]] || return 0
  [[ "$BENCH_NICE" =~ ^-?[0-9]+$ ]] || die "BENCH_NICE must be an integer (got '$BENCH_NICE')"
  # shellcheck disable=SC2016
  PRIO=(setsid --wait sh -c 'echo "$0" > /proc/self/autogroup 2>/dev/null; exec "$@"' "$BENCH_NICE"
        nice -n "$BENCH_NICE")
}

# Installs the Debian package 'liggghts' if liggghts or mpirun is missing; sets MPIRUN.
setup_liggghts() {
  if ! command -v liggghts >/dev/null 2>&1 || ! command -v mpirun >/dev/null 2>&1; then
    log "liggghts/mpirun not found; installing the Debian package 'liggghts' (pulls Open MPI)"
    local sudo=
    if [[ $(id -u) -ne 0 ]]; then
      command -v sudo >/dev/null 2>&1 || die "not root and no sudo: install liggghts by hand (apt-get install liggghts)"
      sudo=sudo
    fi
    export DEBIAN_FRONTEND=noninteractive
    if ! $sudo apt-get install -y -q liggghts; then
      log "install failed; running apt-get update and retrying"
      $sudo apt-get update -q
      $sudo apt-get install -y -q liggghts || die "apt-get install liggghts failed"
    fi
  fi
  # shellcheck disable=SC2034  # used by the caller
  LIGGGHTS_VERSION=$(dpkg-query -W -f='${Version}' liggghts 2>/dev/null || echo unknown)
  # Open MPI refuses to run as root without --allow-run-as-root. --bind-to none: by default two
  # single-rank jobs both bind to core 0; we never run two at once, but stay unbound anyway so
  # LIGGGHTS ranks are scheduled like demcal's threads.
  MPIRUN=(mpirun --bind-to none)
  [[ $(id -u) -eq 0 ]] && MPIRUN+=(--allow-run-as-root)
  # shellcheck disable=SC2206
  [[ -n "${MPIRUN_EXTRA:-}" ]] && MPIRUN+=($MPIRUN_EXTRA)
  return 0
}

# ---------------------------------------------------------------- background-load guard
# The box has 2 cores; any other busy process distorts timings.
HZ=$(getconf CLK_TCK)
# Busy CPU-seconds of the whole machine (user+nice+system+irq+softirq+steal) ...
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
  # The cores the job itself held on average (its CPU seconds over its wall seconds).
  # shellcheck disable=SC2034  # read by the scripts that source this file
  RUN_CORES=$(awk -v c0="$c0" -v c1="$c1" -v t0="$t0" -v t1="$t1" \
    'BEGIN { if (t1 - t0 <= 0) { print 0; exit } printf "%.3f", (c1 - c0) / (t1 - t0) }')
  return $rc
}
is_noisy() { awk -v l="$BG_LOAD" -v m="$NOISE_MAX" 'BEGIN { exit !(l >= m) }'; }

# retrying ATTEMPT ARGS...: runs "ATTEMPT TRY ARGS..." (TRY = 0, 1, ...; it must run its job
# under `measured` and print its result line) after waiting for an idle machine, and repeats it
# while the run was noisy, up to MAX_RETRY times; a noisy run kept in the end is counted in
# NOISY_RUNS. Returns the attempt's status.
NOISY_RUNS=0
retrying() {
  local attempt=$1 try; shift
  for ((try = 0; ; try++)); do
    wait_idle
    "$attempt" "$try" "$@" || return $?
    if is_noisy && (( try < MAX_RETRY )); then log "    noisy run discarded, repeating"; continue; fi
    if is_noisy; then NOISY_RUNS=$((NOISY_RUNS + 1)); fi
    return 0
  done
}

# ---------------------------------------------------------------- one demcal run
# The value of "KEY: value" in a demcal_bench output file (last occurrence; empty if none).
bench_value() { awk -v k="$1:" '$1 == k { v = $2 } END { print v }' "$2"; }

DEMCAL_OUT=""
# demcal_attempt TRY LABEL TAG ARGS...: one timed "demcal_bench throughput ARGS..." (needs
# DEMCAL_BIN, PRIO), output in demcal.TAG.tryTRY.out (DEMCAL_OUT). Sets RATE (bodies x steps / s)
# and SPHERE_RATE; returns 1 if the run failed or printed no rate.
demcal_attempt() {
  local try=$1 label=$2 tag=$3; shift 3
  DEMCAL_OUT="demcal.$tag.try$try.out"
  if ! measured "${PRIO[@]}" "$DEMCAL_BIN" throughput "$@" > "$DEMCAL_OUT" 2>&1; then
    tail -20 "$DEMCAL_OUT" >&2 || true
    log "WARNING: demcal run ($label) failed"
    return 1
  fi
  RATE=$(bench_value particle_steps_per_s "$DEMCAL_OUT")
  SPHERE_RATE=$(bench_value sphere_steps_per_s "$DEMCAL_OUT")
  if [[ -z "$RATE" ]]; then
    tail -20 "$DEMCAL_OUT" >&2 || true
    log "WARNING: demcal output ($label) has no 'particle_steps_per_s:' line"
    return 1
  fi
  SPHERE_RATE=${SPHERE_RATE:-$RATE}
  log "  demcal   $label: $(fmt_m "$RATE") particle-steps/s  [other load $BG_LOAD cores]"
}
