#!/usr/bin/env bash
# Benchmark of a whole calibration: two parameters (BP-BP sliding and
# rolling friction) against two targets of SYNTHETIC twin data, at the fidelity the data were made
# at (--quick). Prints wall time, simulations run, and the recovered values against the truth
# (truth.json beside the study's measurement table) in units of the reported sigma.
# Usage: bash bench/calibration_two_targets.sh [BUILD_DIR]
# Environment: STUDY=examples/calibrate_bp_friction_rig.json (default: repose angle + discharge
#   time of the small rig, truth 0.25 / 0.10, which the two targets separate; the other bundled
#   twin, examples/calibrate_bp_two_targets.json at truth 0.5 / 0.2, is one no target here can
#   pin: docs/calibration.md "Which targets separate mu_s and mu_r").
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
study=${STUDY:-examples/calibrate_bp_friction_rig.json}
out=$(mktemp -d /tmp/demcal_bench_calib.XXXXXX)
start=$(date +%s.%N)
status=0
"$build/apps/demcal" calibrate "$study" --out "$out" --quick --quiet || status=$?
end=$(date +%s.%N)
python3 - "$out/result.json" "$study" "$start" "$end" "$status" <<'PY'
import json, os, sys
r = json.load(open(sys.argv[1]))
study = json.load(open(sys.argv[2]))
table = os.path.join(os.path.dirname(sys.argv[2]), study["measurements"])
truth = json.load(open(os.path.join(os.path.dirname(table), "truth.json")))["truth"]
wall = float(sys.argv[4]) - float(sys.argv[3])
print(f"study {sys.argv[2]}")
print(f"calibration wall time (2 cores): {wall:.0f} s  (exit {sys.argv[5]}, termination {r['termination']})")
print(f"candidates {r['candidates']}, batches {r['batches']}, simulations run {r['replicates_run']} "
      f"(+{r['replicates_reused']} from the journal)")
keys = {"mu_s_BP_BP": "sliding_friction", "mu_r_BP_BP": "rolling_friction"}
for p in r["parameters"]:
    t = truth[keys[p["name"]]]; s = p["sigma"]
    z = "n/a" if s in (None, 0) else f"{(p['value'] - t) / s:+.2f} sigma"
    print(f"{p['name']}: {p['value']:.4g} +- {s if s is not None else 'inf'} (truth {t}; {z}; "
          f"identifiable {p['identifiable']})")
print("correlation:", r["correlation"])
print("identifiability:", r["identifiability"]["summary"].strip().replace("\n", " | "))
PY
echo "outputs: $out" >&2
