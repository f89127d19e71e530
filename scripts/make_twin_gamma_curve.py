#!/usr/bin/env python3
"""SYNTHETIC data: the twin of the Gamma-per-coating calibration (twin (c)).

Recipe (re-runnable: `python3 scripts/make_twin_gamma_curve.py BUILD_DIR`):
 1. The heap of examples/diagnose/aor_bp_heap.json (BP of Alizadeh et al. 2018 as spheres in the
    small pseudo-2D box, 0.7 s heaps) with the file's own friction (sliding 0.62, rolling 0.10;
    the studies hold it fixed, as the paper holds the uncoated friction fixed when it fits Gamma
    per coating) and the BP-BP interfacial
    energy following the LINEAR curve Gamma(w) = C0 + C1 w (TRUTH below) at PEG coating levels
    w = 1, 2 and 3 wt%. The values are kept where the heap's flank stays readable at quick
    fidelity (angles of about 20-30 deg); the paper's own Gamma (0.05-0.35 J/m2 on 0.26 mm EP at
    full stiffness) leaves flanks too rough to read on this rig (docs/calibration.md).
 2. `demcal experiment aor --quick`, REPLICATES replicates with base seed SEED (not the studies'
    seed 2018: the "measurement" has its own packings); the mean over the heaps that gave a value
    is the noise-free value of the angle and of the heap height.
 3. Measurement noise: plus a seeded Gaussian draw (random.Random(NOISE_SEED)) of 1.0 deg for the
    angle and 3 % for the height (as make_diagnose_twins.py); the row's uncertainty combines that
    noise with the replicate mean's standard error (the noise-free value is itself an estimate).
Writes datasets/synthetic/bp_gamma_curve_twin/measurements.csv (provenance: synthetic) and the truth
to truth.json beside it, which only the scoring test reads
(tests/workflow/calibration/calibrate_twin_long_test.cc).
"""
import json, math, os, random, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_diagnose_twins as twins  # noqa: E402  (the rig's model, runner and noise model)

LEVELS = [1.0, 2.0, 3.0]
TRUTH = {"C0_J_m2": 0.004, "C1_J_m2_per_wt_pct": 0.006}
SEED, REPLICATES, NOISE_SEED = 7101, 12, 11
OBSERVABLES = ("angle_deg", "heap_height_m")
OUT = os.path.join(twins.ROOT, "datasets", "synthetic", "bp_gamma_curve_twin")


def gamma(w):
    return TRUTH["C0_J_m2"] + TRUTH["C1_J_m2_per_wt_pct"] * w


def heap_model(w):
    model = json.load(open(os.path.join(twins.ROOT, "examples", "diagnose", "aor_bp_heap.json")))
    model["seed"] = SEED
    pair = dict(model["interactions"]["default"], materials=["BP", "BP"], interfacial_energy_J_m2=gamma(w))
    model["interactions"]["pairs"].append(pair)  # as a study's Gamma parameter sets it
    return model


def mean_and_sem(result, key):
    values = [r[key] for r in result["runs"] if r.get("status") == "ok" and r.get(key) is not None]
    if len(values) < 2:
        return None, None, len(values)
    mean = sum(values) / len(values)
    var = sum((v - mean) ** 2 for v in values) / (len(values) - 1)
    return mean, math.sqrt(var / len(values)), len(values)


def main():
    demcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "apps", "demcal")
    twins.REPLICATES = REPLICATES
    rng = random.Random(NOISE_SEED)
    recipe = (f"SYNTHETIC: demcal aor at quick fidelity on examples/diagnose/aor_bp_heap.json (its friction: sliding 0.62, "
              f"rolling 0.10), Gamma(w) = {TRUTH['C0_J_m2']} + {TRUTH['C1_J_m2_per_wt_pct']} w J/m2, mean of "
              f"{REPLICATES} replicates (seed {SEED}) plus seeded Gaussian noise; scripts/make_twin_gamma_curve.py")
    os.makedirs(OUT, exist_ok=True)
    noise_free, rows = {}, []
    with tempfile.TemporaryDirectory() as tmp:
        for w in LEVELS:
            result = twins.run(demcal, "aor", heap_model(w), tmp, f"aor_{w}")
            for obs in OBSERVABLES:
                mean, sem, n = mean_and_sem(result, obs)
                if mean is None:
                    print(f"{obs} at {w} wt%: {n} heaps gave a value; row left out", file=sys.stderr)
                    continue
                unit, noise = twins.NOISE[obs][0], twins.NOISE[obs][1](mean)
                noise_free[f"{obs}|{w:g}"] = {"value": mean, "replicate_mean_sem": sem, "replicates": n}
                u = math.hypot(noise, sem)
                rows.append(f'{obs},{unit},BP,{w:g},pseudo-2D heap,{mean + rng.gauss(0, noise):.6g},{u:.3g},{n},'
                            f'synthetic,"{recipe}"\n')
    with open(os.path.join(OUT, "measurements.csv"), "w") as f:
        f.write("observable,unit,material,coating_PEG_wt_pct,test,value,uncertainty,repeats,provenance,source\n")
        f.writelines(rows)
    json.dump({"truth": TRUTH, "gamma_J_m2": {f"{w:g}": gamma(w) for w in LEVELS},
               "noise_free": noise_free, "recipe": recipe},
              open(os.path.join(OUT, "truth.json"), "w"), indent=2)
    print(f"{len(rows)} rows -> {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
