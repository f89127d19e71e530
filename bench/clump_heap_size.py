#!/usr/bin/env python3
"""Does a calibrated clump's repose angle depend on the heap's size, its pour and its slab?

The clumps workflow calibrates BP's shape (4-sphere chain, aspect ratio 3.36; docs/reproduce_clumps.md,
Fig. 3) on a 2.5 g heap in the 60 mm repose box (examples/aor_bp.json), where it stands at the
measured 40 deg; the same clumps in the 30.85 g segregation heap stand about 12 deg higher
(docs/experiments/segregation_angle.md). This script pours BP alone at quick fidelity (size x5)
into variants of the repose box, each `demcal experiment aor FILE --quick --threads 1` with the
file's 3 replicates (seeds drawn from the file's seed 2018), Table 1's friction and rolling
friction (0.10) as in the example. Arms (mass, box width, slab depth, pour height, feed rate):
  S       the calibration heap: 2.5 g, 60 mm, 16 mm, 60 mm, 18.5 g/s (0.14 s of pour)
  Sslow   the same 2.5 g poured 10x slower (1.85 g/s, 1.35 s): the pour's duration alone
  M       4x the mass (10 g) in a 120 mm box from 90 mm at 18.5 g/s: a heap about twice as tall
  Mslow   M poured 4x slower (4.6 g/s): M's heap built over the time S_slow took per gram
  M32     M's heap in a 32 mm slab: 2x the mass at 2x the rate (same height, same pour time),
          so only the slab's depth (its confinement of the chains) differs from M
  L       the segregation box's size: 30 g, 200 mm, from 120 mm at 18.5 g/s, no funnel
Every box keeps the 12 mm feed and the settle criterion; max_time_s = pour time + 3 s. Resumable:
an arm whose result.json exists is not run again. Writes OUT/runs.csv (one row per heap) and
OUT/arms.csv (mean +- sem per arm). Results and reading: docs/experiments/segregation_angle.md.

  python3 bench/clump_heap_size.py build/apps/demcal OUT [--arms S,Sslow,M,Mslow,M32,L]
"""
import argparse
import copy
import json
import os
import subprocess
import sys

from heap_runs import cpu_seconds, write_tables

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AOR_EXAMPLE = os.path.join(REPO, "examples", "aor_bp.json")
BP_CLUMP = {"ellipsoid": {"semi_axes": [3.360714718649257, 1.0, 1.0], "sphere_count": 4}}
RATE = 0.0185  # kg/s, BP's feed rate in Table 1, as in examples/aor_bp.json
# arm: mass [kg], box width [m], slab depth [m], pour height [m], feed rate [kg/s]
ARMS = {
    "S": (0.0025, 0.06, 0.016, 0.06, RATE),
    "Sslow": (0.0025, 0.06, 0.016, 0.06, 0.00185),  # RATE / 10
    "M": (0.010, 0.12, 0.016, 0.09, RATE),
    "Mslow": (0.010, 0.12, 0.016, 0.09, RATE / 4),
    "M32": (0.020, 0.12, 0.032, 0.09, 2 * RATE),
    "L": (0.030, 0.20, 0.016, 0.12, RATE),
}


def variant(arm):
    mass, width, depth, height, rate = ARMS[arm]
    exp = json.load(open(AOR_EXAMPLE))
    exp["species"][0]["clump"] = copy.deepcopy(BP_CLUMP)
    exp["replicates"] = 3
    aor = exp["aor"]
    aor["feed"]["mass_kg"] = mass
    aor["feed"]["mass_rate_kg_s"] = rate
    aor["width_m"], aor["depth_m"], aor["pour_height_m"] = width, depth, height
    aor["settle"]["max_time_s"] = max(3.0, mass / rate + 3.0)
    return exp


def run_arm(demcal, out, arm):
    folder = os.path.join(out, arm)
    if os.path.exists(os.path.join(folder, "result.json")):
        return
    params = os.path.join(out, arm + ".json")
    json.dump(variant(arm), open(params, "w"), indent=1)
    with open(os.path.join(out, arm + ".err"), "w") as err:
        subprocess.run(["/usr/bin/time", "-v", demcal, "experiment", "aor", params, "--out", folder,
                        "--quick", "--threads", "1", "--quiet"], stderr=err, check=False)


def summarise(out, arms):
    rows = []
    for arm in arms:
        try:
            result = json.load(open(os.path.join(out, arm, "result.json")))
        except (OSError, ValueError):
            continue
        cpu = cpu_seconds(os.path.join(out, arm + ".err")) / max(1, len(result["runs"]))
        for r in result["runs"]:
            rows.append({"arm": arm, "replicate": r["replicate"], "status": r["status"],
                         "angle_deg": r.get("angle_deg", float("nan")),
                         "heap_height_m": r.get("heap_height_m", float("nan")),
                         "particles": r.get("particles", float("nan")),
                         "settle_time_s": r.get("settle_time_s", float("nan")),
                         "cpu_s_per_heap": cpu})
    if not rows:
        return
    write_tables(out, rows, arms, ["angle_deg", "heap_height_m", "particles", "cpu_s_per_heap"],
                 keep=lambda r: r["status"] == "ok")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("demcal")
    ap.add_argument("out")
    ap.add_argument("--arms", default=",".join(ARMS))
    ap.add_argument("--summary-only", action="store_true")
    a = ap.parse_args()
    arms = a.arms.split(",")
    unknown = [x for x in arms if x not in ARMS]
    if unknown:
        sys.exit(f"unknown arm(s) {unknown}; known: {list(ARMS)}")
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    if not a.summary_only:
        for arm in arms:
            run_arm(os.path.abspath(a.demcal), out, arm)
    summarise(out, arms)


if __name__ == "__main__":
    main()
