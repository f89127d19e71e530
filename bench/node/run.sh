#!/usr/bin/env bash
# run.sh -- the scaling measurements of bench/scaling.sh on a many-core node, in one bounded run
# (the device tool lends such a node for minutes, without package access): unpacks the bundle
# of bench/node/pack.sh, then runs, each part under what is left of BUDGET_S,
#   1. the 200,000-sphere dense bed and pour, demcal 1..16 threads against LIGGGHTS 1..16 ranks
#   2. the 20,000-sphere bed and pour, the same
#   3. `mpirun -np CORES demcal reproduce alizadeh2018 --quick` (the farm), against the wall-time
#      model at 1, 2, CORES, 64 and 512 ranks from its journal (demcal journal-stats --model-ranks)
# and writes each part's output to $OUT (machine.txt, scaling_200k.txt, scaling_20k.txt,
# farm.txt), so that a part cut short still returns what it measured.
#
# usage (repository root on the node; the bundle carried in .devcarry):
#   OUT=/some/dir bash bench/node/run.sh
# Environment: BUNDLE=.devcarry/bundle.tgz  BUDGET_S=540  PARTS="200k 20k farm"
#   SIZES_*/NSTEPS_* below for a shorter look; a local dry run: PARTS=20k NSTEPS_SMALL=50
#   SIZES_SMALL=2000 SETTLE_SMALL=500 OUT=/tmp/o bash bench/node/run.sh
set -uo pipefail
START=$(date +%s)
BUNDLE=${BUNDLE:-.devcarry/bundle.tgz}
BUDGET_S=${BUDGET_S:-540}
PARTS=${PARTS:-200k 20k farm}
SIZES_LARGE=${SIZES_LARGE:-200000}; NSTEPS_LARGE=${NSTEPS_LARGE:-400}; SETTLE_LARGE=${SETTLE_LARGE:-8000}
SIZES_SMALL=${SIZES_SMALL:-20000};  NSTEPS_SMALL=${NSTEPS_SMALL:-2000}; SETTLE_SMALL=${SETTLE_SMALL:-16000}
: "${OUT:?set OUT to the folder for the results}"
mkdir -p "$OUT"
elapsed() { echo $(( $(date +%s) - START )); }
left() { echo $(( BUDGET_S - $(elapsed) )); }
note() { echo "[run.sh t+$(elapsed)s] $*" | tee -a "$OUT/run.log" >&2; }

unpack=${TMPDIR:-/tmp}/demcal-node
if ! { mkdir -p "$unpack" && tar xzf "$BUNDLE" -C "$unpack"; }; then note "cannot unpack $BUNDLE"; exit 1; fi
D=$unpack/bundle
# Open MPI relocated: every path it compiled in is given again under the bundle.
export OPAL_PREFIX=$D/usr OPAL_SYSCONFDIR=$D/etc/openmpi OPAL_DATADIR=$D/usr/share
export OPAL_LIBDIR=$D/usr/lib/x86_64-linux-gnu/openmpi/lib OPAL_PKGDATADIR=$D/usr/share/openmpi
export PMIX_PREFIX=$D/usr/lib/x86_64-linux-gnu/pmix2 PMIX_INSTALL_PREFIX=$D/usr/lib/x86_64-linux-gnu/pmix2
export PMIX_MCA_mca_base_component_path=$D/usr/lib/x86_64-linux-gnu/pmix2/lib/pmix
export OMPI_MCA_btl_vader_single_copy_mechanism=none  # containers often forbid CMA
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export PATH=$D/usr/bin:$D/demcal:$PATH
export LD_LIBRARY_PATH=$D/demcal/lib:$D/usr/lib/x86_64-linux-gnu:$D/usr/lib/x86_64-linux-gnu/openmpi/lib:$D/usr/lib/x86_64-linux-gnu/pmix2/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
# scaling.sh finds demcal_bench under BUILD_DIR/bench.
mkdir -p "$unpack/build/bench" && ln -sf "$D/demcal/demcal_bench" "$unpack/build/bench/demcal_bench"

{ echo "demcal commit: $(cat "$D/demcal/commit")"; date -u; nproc
  lscpu | grep -E "Model name|Socket|Core|Thread|NUMA|L2|L3"; free -g | head -2
  mpirun --version | head -1; } > "$OUT/machine.txt" 2>&1
cat "$OUT/machine.txt" >&2

scaling() {  # $1 tag, then environment for scaling.sh
  local tag=$1; shift
  local budget; budget=$(left)
  (( budget > 30 )) || { note "$tag skipped: ${budget}s left"; return; }
  note "$tag: up to ${budget}s"
  env "$@" BUILD_DIR="$unpack/build" timeout "$budget" bash bench/scaling.sh \
    > "$OUT/scaling_$tag.txt" 2>&1
  note "$tag: rc $? ($(grep -c ratio "$OUT/scaling_$tag.txt") ratio lines)"
}

for part in $PARTS; do
  case $part in
    200k) scaling 200k SIZES="$SIZES_LARGE" NSTEPS="$NSTEPS_LARGE" WARMUP=50 SETTLE_STEPS="$SETTLE_LARGE" ;;
    20k)  scaling 20k SIZES="$SIZES_SMALL" NSTEPS="$NSTEPS_SMALL" WARMUP=100 SETTLE_STEPS="$SETTLE_SMALL" ;;
    farm)
      budget=$(left)
      if (( budget > 60 )); then
        ranks=$(nproc); dir=${TMPDIR:-/tmp}/farm-quick
        note "farm: mpirun -np $ranks demcal reproduce alizadeh2018 --quick, up to ${budget}s"
        t0=$(date +%s)
        timeout "$budget" mpirun --bind-to none -np "$ranks" demcal reproduce alizadeh2018 --quick \
          --threads 1 --out "$dir" > "$OUT/farm.txt" 2>&1
        echo "farm rc $? wall $(( $(date +%s) - t0 )) s on $ranks ranks" >> "$OUT/farm.txt"
        demcal journal-stats "$dir" --model-ranks "1,2,$ranks,64,512" >> "$OUT/farm.txt" 2>&1
        cp "$dir/summary.json" "$OUT/farm_summary.json" 2>/dev/null
        note "farm: $(tail -n 1 "$OUT/farm.txt")"
      else
        note "farm skipped: ${budget}s left"
      fi ;;
    *) note "unknown part '$part' (allowed: 200k 20k farm)" ;;
  esac
done
grep -h -E "ratio|speed-up|identical" "$OUT"/scaling_*.txt 2>/dev/null | tee "$OUT/summary.txt" >&2
note "done"
