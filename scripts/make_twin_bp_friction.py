#!/usr/bin/env python3
"""SYNTHETIC data: the twin dataset of examples/calibrate_bp_two_targets.json.

Recipe (re-runnable: `python3 scripts/make_twin_bp_friction.py BUILD_DIR`):
 1. The model of examples/aor_bp.json and examples/discharge_bp.json (BP of Alizadeh et al.
    2018 as spheres) with the BP-BP friction set to the truth below.
 2. `demcal experiment aor` and `demcal experiment discharge` at the files' quick fidelity,
    REPLICATES replicates with base seed SEED (not the study's seed: the "measurement" has its
    own packings); the means of angle_deg and mass_flow_kg_s (and the free observables of the
    same runs) are the noise-free values.
 3. Measurement noise: each value plus a seeded Gaussian draw (random.Random(NOISE_SEED)) of the
    stated uncertainty: 1.0 deg for angles (a typical repose repeatability), 3 % for flows,
    times and densities (a typical discharge repeatability).
Writes datasets/synthetic/bp_friction_twin/measurements.csv (provenance: synthetic) and the
truth to truth.json beside it, which only tests read, to score.
"""
import json, os, random, subprocess, sys, tempfile

TRUTH = {"sliding_friction": 0.5, "rolling_friction": 0.2}
SEED, REPLICATES, NOISE_SEED = 7001, 4, 1
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "datasets", "synthetic", "bp_friction_twin")


def run(demcal, kind, path, tmp):
    model = json.load(open(os.path.join(ROOT, "examples", path)))
    model["interactions"]["default"].update(TRUTH)
    scene = os.path.join(tmp, kind + ".json")
    json.dump(model, open(scene, "w"))
    out = os.path.join(tmp, kind + ".out")
    subprocess.run([demcal, "experiment", kind, scene, "--out", out, "--quick", "--replicates",
                    str(REPLICATES), "--quiet"], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "result.json")))


def main():
    demcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "apps", "demcal")
    rng = random.Random(NOISE_SEED)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        aor = run(demcal, "aor", "aor_bp.json", tmp)
        dis = run(demcal, "discharge", "discharge_bp.json", tmp)
    recipe = ("SYNTHETIC: demcal at quick fidelity, BP-BP sliding friction 0.5, rolling friction 0.2, "
              "mean of 4 replicates (seed 7001) plus seeded Gaussian noise of the stated uncertainty; "
              "scripts/make_twin_bp_friction.py")
    for observable, unit, value, u, test in [
            ("angle_deg", "deg", aor["angle_deg"], 1.0, "pseudo-2D heap"),
            ("mass_flow_kg_s", "kg/s", dis["mass_flow_kg_s"], 0.03 * dis["mass_flow_kg_s"], "funnel"),
            ("discharge_time_s", "s", dis["discharge_time_s"], 0.03 * dis["discharge_time_s"], "funnel")]:
        rows.append((observable, unit, "BP", test, value + rng.gauss(0, u), u))
    with open(os.path.join(OUT, "measurements.csv"), "w") as f:
        f.write("observable,unit,material,test,value,uncertainty,repeats,provenance,source\n")
        for o, unit, m, test, v, u in rows:
            f.write(f'{o},{unit},{m},{test},{v:.6g},{u:.3g},{REPLICATES},synthetic,"{recipe}"\n')
    json.dump({"truth": TRUTH, "noise_free": {"angle_deg": aor["angle_deg"],
               "mass_flow_kg_s": dis["mass_flow_kg_s"], "discharge_time_s": dis["discharge_time_s"]},
               "recipe": recipe}, open(os.path.join(OUT, "truth.json"), "w"), indent=2)


if __name__ == "__main__":
    main()
