#!/usr/bin/env bash
# compare_export_heap.sh -- does an exported deck reproduce demcal's heap in LIGGGHTS 3.8?
# A small cohesionless slot heap: examples/aor_bp.json at its quick fidelity (spheres x5, about
# 500 grains of d 2.1-2.5 mm poured at 18.5 g/s into the 60 x 16 mm box on a glued base), the
# settle limit cut to MAX_TIME_S. demcal runs REPS replicates (demcal experiment aor --quick);
# LIGGGHTS runs REPS decks written by `demcal export liggghts --fidelity quick` (seeds 1..REPS),
# each measured by demcal's own slot-heap fit (demcal_dump_angle). Prints per-replicate angles
# and, as the last lines:
#   demcal angle (deg): MEAN +- SEM (n)
#   liggghts angle (deg): MEAN +- SEM (n)
# Environment:
#   ROLLING=cdt        the rolling law of both runs: cdt | epsd2 | none
#   MU_R=0.10          the BP-BP rolling coefficient (demcal's convention)
#   CONVERSION=torque  how the deck converts cdt (--rolling-conversion)
#   LIGGGHTS_MU_R=     if set, overrides the deck's BP-BP coefficient (LIGGGHTS' convention), to
#                      find the one that matches
#   REPS=4  MAX_TIME_S=1.2  BUILD_DIR=build  WORK=(temp dir, kept)
#   CHECK=0            1: exit 1 unless the two means agree within 3 combined standard errors
#                      (the [long] test liggghts_heap_long_test.cc runs ROLLING=none CHECK=1)
set -euo pipefail
SCRIPT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO_ROOT=$(cd "$SCRIPT_DIR/.." && pwd)
ROLLING=${ROLLING:-cdt}
MU_R=${MU_R:-0.10}
CONVERSION=${CONVERSION:-torque}
CHECK=${CHECK:-0}
LIGGGHTS_MU_R=${LIGGGHTS_MU_R:-}
REPS=${REPS:-4}
MAX_TIME_S=${MAX_TIME_S:-1.2}
BUILD_DIR=${BUILD_DIR:-build}
[[ "$BUILD_DIR" = /* ]] || BUILD_DIR=$REPO_ROOT/$BUILD_DIR
WORK=${WORK:-$(mktemp -d /tmp/compare_export_heap.XXXXXX)}
mkdir -p "$WORK"
if ! command -v liggghts > /dev/null; then
  echo "liggghts is not installed (apt-get install liggghts)"
  exit 77
fi

make_file() {  # make_file SEED OUT
  python3 - "$REPO_ROOT/examples/aor_bp.json" "$1" "$2" "$ROLLING" "$MU_R" "$MAX_TIME_S" \
    "$REPS" <<'PY'
import json, sys
src, seed, out, rolling, mu, tmax, reps = sys.argv[1:]
f = json.load(open(src))
f["seed"] = int(seed)
f["replicates"] = int(reps)
f["contact_model"]["rolling"] = rolling
f["interactions"]["default"]["rolling_friction"] = float(mu)
f["aor"]["settle"]["max_time_s"] = float(tmax)
json.dump(f, open(out, "w"), indent=1)
PY
}

stats() {  # mean +- sem (n) of the numbers on stdin
  python3 -c 'import sys,statistics as s
v=[float(x) for x in sys.stdin.read().split()]
print(f"{s.mean(v):.2f} +- {s.stdev(v)/len(v)**0.5:.2f} ({len(v)})" if len(v) > 1
      else v)'
}

make_file 2018 "$WORK/heap.json"
nice -n 10 "$BUILD_DIR/apps/demcal" experiment aor "$WORK/heap.json" --quick --out "$WORK/demcal" \
  --threads 1 --quiet > "$WORK/demcal.log" 2>&1 || true
python3 -c 'import json,sys
r=json.load(open(sys.argv[1]))
for x in r["runs"]: print(x["angle_deg"]) if x.get("angle_deg") is not None else None' \
  "$WORK/demcal/result.json" > "$WORK/demcal_angles.txt"
: > "$WORK/liggghts_angles.txt"
for r in $(seq 1 "$REPS"); do
  make_file "$r" "$WORK/heap_$r.json"
  deck=$WORK/liggghts_$r
  "$BUILD_DIR/apps/demcal" export liggghts "$WORK/heap_$r.json" --fidelity quick --out "$deck" \
    --rolling-conversion "$CONVERSION" > "$WORK/export_$r.log" 2>&1
  if [[ -n "$LIGGGHTS_MU_R" ]]; then  # BP-BP is the first entry of the 2x2 matrix
    sed -i -E "s/(coefficientRollingFriction peratomtypepair 2) [^ ]+/\1 $LIGGGHTS_MU_R/" \
      "$deck/in.demcal"
  fi
  (cd "$deck" && nice -n 10 liggghts -in in.demcal -log log.liggghts > /dev/null 2>&1) || true
  "$BUILD_DIR/bench/demcal_dump_angle" "$deck" | awk '{print $2}' \
    >> "$WORK/liggghts_angles.txt" || true
done
echo "work: $WORK  rolling $ROLLING  mu_r $MU_R  conversion $CONVERSION" \
  " liggghts mu_r ${LIGGGHTS_MU_R:-as exported}"
echo "demcal angles: $(tr '\n' ' ' < "$WORK/demcal_angles.txt")"
echo "liggghts angles: $(tr '\n' ' ' < "$WORK/liggghts_angles.txt")"
echo "demcal angle (deg): $(stats < "$WORK/demcal_angles.txt")"
echo "liggghts angle (deg): $(stats < "$WORK/liggghts_angles.txt")"
if [[ "$CHECK" == 1 ]]; then
  python3 - "$WORK/demcal_angles.txt" "$WORK/liggghts_angles.txt" <<'PY'
import statistics as st, sys
a, b = ([float(x) for x in open(p).read().split()] for p in sys.argv[1:])
if len(a) < 2 or len(b) < 2:
    sys.exit(f"too few angles: demcal {len(a)}, liggghts {len(b)}")
sem = (st.variance(a) / len(a) + st.variance(b) / len(b)) ** 0.5
diff = st.mean(b) - st.mean(a)
print(f"difference (deg): {diff:.2f} +- {sem:.2f}; within 3 standard errors: {abs(diff) <= 3 * sem}")
sys.exit(0 if abs(diff) <= 3 * sem else 1)
PY
fi
