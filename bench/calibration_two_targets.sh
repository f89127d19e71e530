#!/usr/bin/env bash
# Benchmark of a whole calibration (issue "Calibration II"): two parameters (BP-BP sliding and
# rolling friction) against two targets (repose angle, funnel mass flow) of SYNTHETIC twin data
# (datasets/synthetic/bp_friction_twin/, made at the quick fidelity: so the study runs --quick).
# Prints wall time, simulations run, and the recovered values against the truth (truth.json) in
# units of the reported sigma. Usage: bash bench/calibration_two_targets.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$(mktemp -d /tmp/demcal_bench_calib.XXXXXX)
start=$(date +%s.%N)
status=0
"$build/apps/demcal" calibrate examples/calibrate_bp_two_targets.json --out "$out" --quick --quiet || status=$?
end=$(date +%s.%N)
python3 - "$out/result.json" datasets/synthetic/bp_friction_twin/truth.json "$start" "$end" "$status" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); truth = json.load(open(sys.argv[2]))["truth"]
wall = float(sys.argv[4]) - float(sys.argv[3])
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
