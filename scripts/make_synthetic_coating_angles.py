#!/usr/bin/env python3
"""SYNTHETIC data: the EP repose angles at 1.5, 2.5 and 3.5 wt% PEG of demcal reproduce alizadeh2018.

The paper (Alizadeh et al. 2018) shows these angles only in its Fig. 6, which we do not have. This
recipe makes stand-ins with demcal itself, so the Gamma-per-coating and Gamma(w) stages have data
at those levels. They are NOT measurements: every row says synthetic, and so does every output
built on them.

Recipe (re-runnable: `python3 scripts/make_synthetic_coating_angles.py BUILD_DIR`):
 1. The model of examples/aor_ep.json (EP of Table 1 as spheres) with the EP-EP rolling friction
    ROLLING (the value at which the uncoated heap stands near the measured 31.0 deg at quick
    fidelity) and the EP-EP interfacial energy Gamma(w) = 0.046 + 0.102 (w - 0.5) J/m2: the line
    through the paper's 0.046 J/m2 at 0.5 wt% (section 2.5.2) and 0.250 J/m2 at 2.5 wt% (section
    2.5.3, read from its Fig. 6).
 2. `demcal experiment aor --quick`, REPLICATES replicates with base seed SEED (not the
    workflow's seed: the "measurement" has its own packings); the mean angle is the noise-free
    value.
 3. Measurement noise: plus a seeded Gaussian draw (random.Random(NOISE_SEED)) of 1.0 deg, the
    repeatability the workflow assumes for every angle.
Writes datasets/synthetic/alizadeh2018_coating_angles/measurements.csv (provenance: synthetic)
and truth.json (the Gamma used and the noise-free angles) beside it.
"""
import json, os, random, subprocess, sys, tempfile

LEVELS = [1.5, 2.5, 3.5]
ROLLING = 0.25
SEED, REPLICATES, NOISE_SEED, NOISE_DEG = 9001, 4, 1, 1.0
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "datasets", "synthetic", "alizadeh2018_coating_angles")


def gamma(w):
    return 0.046 + (0.250 - 0.046) / (2.5 - 0.5) * (w - 0.5)


def angle(demcal, w, tmp):
    model = json.load(open(os.path.join(ROOT, "examples", "aor_ep.json")))
    model["interactions"]["default"]["rolling_friction"] = ROLLING
    model["interactions"]["default"]["interfacial_energy_J_m2"] = gamma(w)
    model["seed"] = SEED
    scene = os.path.join(tmp, f"ep_{w}.json")
    json.dump(model, open(scene, "w"))
    out = os.path.join(tmp, f"ep_{w}.out")
    subprocess.run([demcal, "experiment", "aor", scene, "--out", out, "--quick", "--replicates",
                    str(REPLICATES), "--quiet"], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "result.json")))["angle_deg"]


def main():
    demcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "apps", "demcal")
    rng = random.Random(NOISE_SEED)
    os.makedirs(OUT, exist_ok=True)
    noise_free = {}
    with tempfile.TemporaryDirectory() as tmp:
        for w in LEVELS:
            noise_free[w] = angle(demcal, w, tmp)
    recipe = ("SYNTHETIC (not measured): demcal aor --quick on examples/aor_ep.json with EP-EP "
              f"rolling friction {ROLLING} and Gamma(w) = 0.046 + 0.102 (w - 0.5) J/m2, mean of "
              f"{REPLICATES} replicates (seed {SEED}) plus seeded Gaussian noise of {NOISE_DEG} deg; "
              "scripts/make_synthetic_coating_angles.py")
    with open(os.path.join(OUT, "measurements.csv"), "w") as f:
        f.write("observable,unit,material,coating_PEG_wt_pct,test,value,uncertainty,repeats,"
                "provenance,source\n")
        for w in LEVELS:
            v = noise_free[w] + rng.gauss(0, NOISE_DEG)
            f.write(f'angle_deg,deg,EP,{w},pseudo-2D heap,{v:.4g},{NOISE_DEG},{REPLICATES},'
                    f'synthetic,"{recipe}"\n')
    json.dump({"gamma_J_m2": {str(w): gamma(w) for w in LEVELS},
               "noise_free_angle_deg": {str(w): noise_free[w] for w in LEVELS},
               "rolling_friction_EP_EP": ROLLING, "recipe": recipe},
              open(os.path.join(OUT, "truth.json"), "w"), indent=2)


if __name__ == "__main__":
    main()
