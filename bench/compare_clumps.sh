# shellcheck shell=bash
# compare_clumps.sh -- the clump and JKR cases of the benchmark (sourced by compare_liggghts.sh
# after lib_compare.sh; see bench/README.md).
#
#   clumps: the dense-bed case with 6667 straight 3-sphere rods (20,001 spheres of d = 2 mm),
#           LIGGGHTS (bench/liggghts/in.clump, fix particletemplate/multisphere + fix multisphere,
#           1 rank: the PUBLIC multisphere code is serial and cannot restart, so every LIGGGHTS
#           repetition pours and settles afresh in the timed process, untimed) against
#           demcal_bench --clump 3 (1 thread). Figures: clump-steps/s (bodies) and sphere-steps/s.
#   JKR:    demcal's sphere case with JKR adhesion at cohesion number JKR_COHESION, on the same
#           settled bed as the Hertz-Mindlin runs; LIGGGHTS has no full JKR, so the figure is
#           demcal's cost ratio (Hertz-Mindlin rate / JKR rate, 1 thread).
#
# Uses the caller's NSTEPS, WORK, PRIO, MPIRUN, DEMCAL_BIN, DEMCAL_BED_ARGS and, for the JKR ratio,
# DEM_RATES[1] (the demcal sphere runs on 1 thread).

CLUMP_SPHERES=3
CLUMP_BODIES=6667                                      # round(20000 / 3)
CLUMP_ATOMS=$((CLUMP_BODIES * CLUMP_SPHERES))
JKR_COHESION=${JKR_COHESION:-1e-3}

LIG_CLUMP_RATES="" ; LIG_CLUMP_SPHERE_RATES=""
DEM_CLUMP_RATES="" ; DEM_CLUMP_SPHERE_RATES=""
DEM_JKR_RATES=""
DEMCAL_CLUMP_OK=0 ; DEMCAL_JKR_OK=0
JKR_GAMMA="" ; JKR_COH=""

# Whether demcal_bench knows the clump and JKR options (an older build does not).
detect_demcal_variants() {
  local help
  [[ $HAVE_DEMCAL == 1 ]] || return 0
  help=$("$DEMCAL_BIN" throughput --help 2>/dev/null || true)
  grep -q -- '--clump' <<< "$help" && DEMCAL_CLUMP_OK=1
  grep -q -- '--jkr-cohesion' <<< "$help" && DEMCAL_JKR_OK=1
  return 0
}

liggghts_clump_attempt() {   # $1 = try, $2 = rep
  local try=$1 rep=$2 lg line loop steps atoms
  lg="log.clump.rep$rep.try$try"
  if ! measured "${PRIO[@]}" "${MPIRUN[@]}" -np 1 liggghts -in in.clump -var nsteps "$NSTEPS" \
        -var nclumps "$CLUMP_BODIES" -log "$lg" > "$lg.out" 2>&1; then
    tail -20 "$lg.out" "$lg" >&2 || true
    die "LIGGGHTS clump run rep=$rep failed"
  fi
  line=$(grep '^Loop time of' "$lg" | tail -1)
  loop=$(awk '{ print $4 }' <<< "$line"); steps=$(awk '{ print $9 }' <<< "$line")
  atoms=$(awk '{ print $12 }' <<< "$line")
  [[ "$steps" == "$NSTEPS" ]] || die "unexpected Loop line in $lg: $line"
  [[ "$atoms" == "$CLUMP_ATOMS" ]] || log "WARNING: $atoms spheres (expected $CLUMP_ATOMS) in clump run rep=$rep"
  SPHERE_RATE=$(awk -v a="$atoms" -v s="$steps" -v t="$loop" 'BEGIN { printf "%.6g", a * s / t }')
  RATE=$(awk -v r="$SPHERE_RATE" -v n="$CLUMP_SPHERES" 'BEGIN { printf "%.6g", r / n }')
  log "  liggghts clumps rep=$rep: loop $loop s for $steps steps x $atoms spheres -> $(fmt_m "$RATE") clump-steps/s, $(fmt_m "$SPHERE_RATE") sphere-steps/s  [other load $BG_LOAD cores]"
}

run_liggghts_clump() {       # $1 = rep
  retrying liggghts_clump_attempt "$1"
  LIG_CLUMP_RATES+=" $RATE"; LIG_CLUMP_SPHERE_RATES+=" $SPHERE_RATE"
}

run_demcal_clump() {         # $1 = rep
  [[ $DEMCAL_CLUMP_OK == 1 ]] || return 0
  local bed=()
  [[ ${#DEMCAL_BED_ARGS[@]} -gt 0 ]] && bed=(--bed "$WORK/demcal_clump$CLUMP_SPHERES.bed")
  if ! retrying demcal_attempt "clumps rep=$1" "clump.rep$1" --threads 1 --steps "$NSTEPS" \
       --clump "$CLUMP_SPHERES" "${bed[@]}"; then
    DEMCAL_CLUMP_OK=0; return 0
  fi
  DEM_CLUMP_RATES+=" $RATE"; DEM_CLUMP_SPHERE_RATES+=" $SPHERE_RATE"
}

run_demcal_jkr() {           # $1 = rep
  [[ $DEMCAL_JKR_OK == 1 ]] || return 0
  if ! retrying demcal_attempt "JKR rep=$1" "jkr.rep$1" --threads 1 --steps "$NSTEPS" \
       --jkr-cohesion "$JKR_COHESION" "${DEMCAL_BED_ARGS[@]}"; then
    DEMCAL_JKR_OK=0; return 0
  fi
  DEM_JKR_RATES+=" $RATE"
  JKR_GAMMA=$(bench_value interfacial_energy_J_m2 "$DEMCAL_OUT")
  JKR_COH=$(bench_value cohesion_number "$DEMCAL_OUT")
}

# One repetition of the extra cases; which code goes first alternates with the repetition.
run_clump_and_jkr_rep() {    # $1 = rep
  if (( $1 % 2 )); then run_liggghts_clump "$1"; run_demcal_clump "$1"
  else                  run_demcal_clump "$1"; run_liggghts_clump "$1"; fi
  run_demcal_jkr "$1"
}

# Prints the clump and JKR sections; sets CLUMP_RATIO ("n/a" without demcal figures).
print_clump_and_jkr_summary() {
  local lig dem lig_s dem_s hm jkr
  echo
  echo "=== 3-sphere clumps, median of $REPS ($CLUMP_BODIES rods = $CLUMP_ATOMS spheres, $NSTEPS steps, 1 thread) ==="
  # shellcheck disable=SC2086
  lig=$(median $LIG_CLUMP_RATES)
  # shellcheck disable=SC2086
  lig_s=$(median $LIG_CLUMP_SPHERE_RATES)
  echo "liggghts 1 rank:   $(fmt_m "$lig") clump-steps/s, $(fmt_m "$lig_s") sphere-steps/s   $(format_runs "$LIG_CLUMP_RATES")"
  CLUMP_RATIO=n/a
  if [[ $DEMCAL_CLUMP_OK == 1 && -n "$DEM_CLUMP_RATES" ]]; then
    # shellcheck disable=SC2086
    dem=$(median $DEM_CLUMP_RATES)
    # shellcheck disable=SC2086
    dem_s=$(median $DEM_CLUMP_SPHERE_RATES)
    echo "demcal   1 thread: $(fmt_m "$dem") clump-steps/s, $(fmt_m "$dem_s") sphere-steps/s   $(format_runs "$DEM_CLUMP_RATES")"
    # shellcheck disable=SC2034  # read by compare_liggghts.sh
    CLUMP_RATIO=$(ratio "$dem" "$lig")
  else
    echo "demcal:            (not run: demcal_bench missing, failed or without --clump)"
  fi
  echo
  echo "=== JKR adhesion (demcal only), median of $REPS (sphere case, 1 thread) ==="
  if [[ $DEMCAL_JKR_OK == 1 && -n "$DEM_JKR_RATES" && -n "${DEM_RATES[1]:-}" ]]; then
    # shellcheck disable=SC2086
    hm=$(median ${DEM_RATES[1]})
    # shellcheck disable=SC2086
    jkr=$(median $DEM_JKR_RATES)
    echo "JKR: interfacial energy = $JKR_GAMMA J/m^2 for cohesion number Coh = $JKR_COH"
    echo "     (Coh = (1/(rho g)) [Gamma^5 / (E*^2 R*^8)]^(1/3), R* = r/2, E* = E / (2 (1 - nu^2)))"
    echo "demcal Hertz-Mindlin: $(fmt_m "$hm") particle-steps/s;  JKR: $(fmt_m "$jkr") particle-steps/s   $(format_runs "$DEM_JKR_RATES")"
    echo "jkr cost ratio demcal (JKR/Hertz-Mindlin, 1 thread): $(ratio "$hm" "$jkr")"
  else
    echo "jkr cost ratio demcal (JKR/Hertz-Mindlin, 1 thread): n/a"
  fi
}
