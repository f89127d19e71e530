#!/usr/bin/env python3
"""SYNTHETIC data: the twin datasets of the two-parameter friction studies.

Recipe (re-runnable: `python3 scripts/make_twin_bp_friction.py BUILD_DIR [CASE]`), per CASE:
  bp_friction_twin      examples/calibrate_bp_two_targets.json: the aor_bp / discharge_bp rig,
                        truth sliding 0.5, rolling 0.2, one noise draw (measurements.csv)
  bp_friction_rig_twin  examples/calibrate_bp_friction_rig.json: the small rig of
                        examples/diagnose/ (0.7 s heaps, a 2 g funnel), truth sliding 0.25,
                        rolling 0.10 (below 0.4 the sliding friction still moves the angle and
                        the discharge time: docs/calibration.md "Which targets separate μs and μr"),
                        five noise draws (measurements_noise<k>.csv, k = 1..5) so that the
                        reported sigma can be checked against the spread of the recoveries
 1. The model of the case's experiment files (BP of Alizadeh et al. 2018 as spheres) with the
    BP-BP friction set to the truth below.
 2. `demcal experiment aor` and `demcal experiment discharge` at the files' quick fidelity,
    REPLICATES replicates with base seed SEED (not the study's seed: the "measurement" has its
    own packings); the means of angle_deg and mass_flow_kg_s (and the free observables of the
    same runs) are the noise-free values.
 3. Measurement noise: each value plus a seeded Gaussian draw (random.Random(NOISE_SEED)) of the
    stated uncertainty: 1.0 deg for angles (a typical repose repeatability), 3 % for flows,
    times and densities (a typical discharge repeatability); noise draw k uses NOISE_SEED + k - 1.
Writes datasets/synthetic/<CASE>/measurements*.csv (provenance: synthetic) and the truth to
truth.json beside it, which only tests read, to score.
"""
import json, os, random, subprocess, sys, tempfile

CASES = {
    "bp_friction_twin": {"truth": {"sliding_friction": 0.5, "rolling_friction": 0.2},
                         "aor": "aor_bp.json", "discharge": "discharge_bp.json", "draws": 1},
    "bp_friction_rig_twin": {"truth": {"sliding_friction": 0.25, "rolling_friction": 0.1},
                             "aor": "diagnose/aor_bp_heap.json",
                             "discharge": "diagnose/discharge_bp_small.json", "draws": 5},
}
SEED, REPLICATES, NOISE_SEED = 7001, 4, 1
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(demcal, kind, path, truth, tmp):
    model = json.load(open(os.path.join(ROOT, "examples", path)))
    model["seed"] = SEED
    model["interactions"]["default"].update(truth)
    scene = os.path.join(tmp, kind + ".json")
    json.dump(model, open(scene, "w"))
    out = os.path.join(tmp, kind + ".out")
    subprocess.run([demcal, "experiment", kind, scene, "--out", out, "--quick", "--replicates",
                    str(REPLICATES), "--quiet"], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "result.json")))


def write_table(path, values, draw, recipe):
    rng = random.Random(NOISE_SEED + draw - 1)
    with open(path, "w") as f:
        f.write("observable,unit,material,test,value,uncertainty,repeats,provenance,source\n")
        for observable, unit, value, u, test in values:
            f.write(f'{observable},{unit},BP,{test},{value + rng.gauss(0, u):.6g},{u:.3g},{REPLICATES},'
                    f'synthetic,"{recipe}"\n')


def main():
    demcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "apps", "demcal")
    name = sys.argv[2] if len(sys.argv) > 2 else "bp_friction_twin"
    case = CASES[name]
    out = os.path.join(ROOT, "datasets", "synthetic", name)
    os.makedirs(out, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        aor = run(demcal, "aor", case["aor"], case["truth"], tmp)
        dis = run(demcal, "discharge", case["discharge"], case["truth"], tmp)
    truth = case["truth"]
    recipe = (f"SYNTHETIC: demcal at quick fidelity, BP-BP sliding friction {truth['sliding_friction']}, "
              f"rolling friction {truth['rolling_friction']}, mean of {REPLICATES} replicates (seed {SEED}) "
              f"plus seeded Gaussian noise of the stated uncertainty; scripts/make_twin_bp_friction.py {name}")
    values = [("angle_deg", "deg", aor["angle_deg"], 1.0, "pseudo-2D heap"),
              ("mass_flow_kg_s", "kg/s", dis["mass_flow_kg_s"], 0.03 * dis["mass_flow_kg_s"], "funnel"),
              ("discharge_time_s", "s", dis["discharge_time_s"], 0.03 * dis["discharge_time_s"], "funnel")]
    draws = case["draws"]
    for draw in range(1, draws + 1):
        table = "measurements.csv" if draws == 1 else f"measurements_noise{draw}.csv"
        write_table(os.path.join(out, table), values, draw, recipe)
    json.dump({"truth": truth, "noise_free": {o: v for o, _, v, _, _ in values}, "draws": draws,
               "recipe": recipe}, open(os.path.join(out, "truth.json"), "w"), indent=2)


if __name__ == "__main__":
    main()
