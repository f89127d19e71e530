#!/usr/bin/env bash
# Repose angle of adhesive EP spheres against Γ, for both loads the rolling limit of a JKR contact
# can multiply (contact_model.jkr_rolling_load: "net" and "repulsive"; core/contact/rolling_model.h).
# The heap is examples/aor_ep.json at its calibration fidelity (size x3, stiffness x0.01), with the
# EP–EP pair at rolling friction MU_R (default 0.25: the value that gives the uncoated 31.0° of
# Table 1 at this fidelity, 31.5 ± 1.4°, measured 2026-12-02) and interfacial energy Γ at the
# simulation stiffness 0.25 GPa (carried to the fidelity at constant Cohesion number like every Γ).
# REPLICATES seeded heaps per point (default 4). Writes OUT/table.csv:
#   jkr_rolling_load, gamma_J_m2, angle_deg, angle_sem_deg, replicates_ok, replicates,
#   heap_height_mean_m
# and each point's `demcal experiment aor` outputs in OUT/<load>_<gamma>/.
#
#   bench/jkr_rolling_load.sh build/apps/demcal /tmp/jkr_load [gamma_J_m2 ...]
set -euo pipefail

if [[ $# -lt 2 || ! -x "$1" ]]; then
  echo "usage: $0 DEMCAL_BINARY OUT_DIR [gamma_J_m2 ...]  (default: 0 0.01 0.046 0.1 0.2)" >&2
  exit 2
fi
demcal=$(realpath "$1")
out=$(realpath -m "$2")
shift 2
gammas=("$@")
[[ ${#gammas[@]} -eq 0 ]] && gammas=(0 0.01 0.046 0.1 0.2)
mu_r=${MU_R:-0.25}
replicates=${REPLICATES:-4}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"

echo "jkr_rolling_load,gamma_J_m2,angle_deg,angle_sem_deg,replicates_ok,replicates,heap_height_mean_m" \
  > "$out/table.csv.part"
for load in net repulsive; do
  for gamma in "${gammas[@]}"; do
    dir="$out/${load}_${gamma}"
    mkdir -p "$dir"
    python3 - "$here/examples/aor_ep.json" "$dir/params.json" "$load" "$gamma" "$mu_r" <<'EOF'
import json, sys
src, dst, load, gamma, mu_r = sys.argv[1:]
d = json.load(open(src))
d["contact_model"]["jkr_rolling_load"] = load
d["interactions"]["pairs"].append({"materials": ["EP", "EP"], "sliding_friction": 0.75,
    "rolling_friction": float(mu_r), "restitution": 0.1, "interfacial_energy_J_m2": float(gamma)})
d["description"] = ("bench/jkr_rolling_load.sh: examples/aor_ep.json with EP-EP rolling friction "
    f"{mu_r}, interfacial energy {gamma} J/m2, jkr_rolling_load {load}")
json.dump(d, open(dst, "w"), indent=1)
EOF
    # A point whose heaps give no angle (columns) exits non-zero but still writes result.json.
    "$demcal" experiment aor "$dir/params.json" --out "$dir" --replicates "$replicates" --quiet || true
    python3 - "$dir/result.json" "$load" "$gamma" >> "$out/table.csv.part" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
fmt = lambda v: "" if v is None else f"{v:.6g}"
heights = [run["heap_height_m"] for run in r["runs"] if run.get("heap_height_m") is not None]
print(",".join([sys.argv[2], sys.argv[3], fmt(r["angle_deg"]), fmt(r["angle_sem_deg"]),
                str(r["replicates_ok"]), str(r["replicates"]),
                fmt(sum(heights) / len(heights) if heights else None)]))
EOF
  done
done
mv "$out/table.csv.part" "$out/table.csv"
column -s, -t "$out/table.csv"
