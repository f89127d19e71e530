#!/usr/bin/env python3
"""SYNTHETIC data: the EP repose angles at 1.5, 2.5 and 3.5 wt% PEG of demcal reproduce alizadeh2018.

The paper (Alizadeh et al. 2018) shows these angles only in its Fig. 6, which we do not have. This
recipe makes stand-ins with demcal itself, so the Gamma-per-coating and Gamma(w) stages have data
at those levels. They are NOT measurements: every row says synthetic, and so does every output
built on them.

Recipe (re-runnable: `python3 scripts/make_synthetic_coating_angles.py BUILD_DIR [quick|default]`,
the fidelity of the heaps, default (examples/aor_ep.json's calibration fidelity) if not given):
 1. The model of examples/aor_ep.json (EP of Table 1 as spheres; its angle reading: the fit, else
    the paper's two points) with the EP-EP rolling friction ROLLING (0.25: the uncoated heap
    stands at 31.5 +- 1.4 deg at the calibration fidelity, measured 2026-12-02 with
    bench/jkr_rolling_load.sh; the measured value is 31.0) and the EP-EP interfacial energy
    Gamma(w) = 0.046 + 0.102 (w - 0.5) J/m2: the line through the paper's 0.046 J/m2 at 0.5 wt%
    (section 2.5.2) and 0.250 J/m2 at 2.5 wt% (section 2.5.3, read from its Fig. 6).
 2. `demcal experiment aor` (--quick only if FIDELITY is quick), REPLICATES replicates with base
    seed SEED (not the workflow's seed: the "measurement" has its own packings); the mean over
    the replicates with an angle is the noise-free value.
 3. Measurement noise: plus a seeded Gaussian draw (random.Random(NOISE_SEED)) of 1.0 deg, the
    repeatability the workflow assumes for every angle. The row's uncertainty combines that noise
    with the replicate mean's standard error; its `repeats` is the number of replicates with an
    angle.
Writes datasets/synthetic/alizadeh2018_coating_angles/measurements.csv (provenance: synthetic)
and truth.json (the Gamma used, the noise-free angles and the runs' statuses) beside it. A level
where fewer than 2 heaps give an angle (rough adhesive flanks that neither a fit nor the two
points can read) gets no row, since no spread can be stated; truth.json and the README say so.
"""
import json, os, random, subprocess, sys, tempfile

LEVELS = [1.5, 2.5, 3.5]
ROLLING = 0.25
SEED, REPLICATES, NOISE_SEED, NOISE_DEG = 9001, 6, 1, 1.0
FIDELITY = sys.argv[2] if len(sys.argv) > 2 else "default"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "datasets", "synthetic", "alizadeh2018_coating_angles")


def gamma(w):
    return 0.046 + (0.250 - 0.046) / (2.5 - 0.5) * (w - 0.5)


def angle(demcal, w, tmp):
    model = json.load(open(os.path.join(ROOT, "examples", "aor_ep.json")))
    pair = dict(model["interactions"]["default"], rolling_friction=ROLLING,
                interfacial_energy_J_m2=gamma(w))  # EP-EP only, as demcal reproduce sets it
    model["interactions"]["pairs"].append(dict({"materials": ["EP", "EP"]}, **pair))
    model["seed"] = SEED
    scene = os.path.join(tmp, f"ep_{w}.json")
    json.dump(model, open(scene, "w"))
    out = os.path.join(tmp, f"ep_{w}.out")
    quick = ["--quick"] if FIDELITY == "quick" else []
    subprocess.run([demcal, "experiment", "aor", scene, "--out", out, "--replicates",
                    str(REPLICATES), "--quiet"] + quick, stdout=subprocess.DEVNULL)
    result = json.load(open(os.path.join(out, "result.json")))
    statuses = sorted({run["status"] for run in result["runs"]})
    return result["angle_deg"], statuses, result["angle_sem_deg"], result["replicates_ok"]


def main():
    demcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "apps", "demcal")
    rng = random.Random(NOISE_SEED)
    os.makedirs(OUT, exist_ok=True)
    noise_free, statuses, sem, ok = {}, {}, {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for w in LEVELS:
            noise_free[w], statuses[w], sem[w], ok[w] = angle(demcal, w, tmp)
    recipe = (f"SYNTHETIC (not measured): demcal aor at the {FIDELITY} fidelity on examples/aor_ep.json with EP-EP "
              f"rolling friction {ROLLING} and Gamma(w) = 0.046 + 0.102 (w - 0.5) J/m2, mean of "
              f"{REPLICATES} replicates (seed {SEED}) plus seeded Gaussian noise of {NOISE_DEG} deg (uncertainty: that noise and the replicate mean's standard error combined); "
              "scripts/make_synthetic_coating_angles.py")
    with open(os.path.join(OUT, "measurements.csv"), "w") as f:
        f.write("observable,unit,material,coating_PEG_wt_pct,test,value,uncertainty,repeats,"
                "provenance,source\n")
        for w in LEVELS:
            if noise_free[w] is None or ok[w] < 2:  # no spread to state: no row (see truth.json)
                continue
            v = noise_free[w] + rng.gauss(0, NOISE_DEG)
            # The stand-in differs from demcal's expected angle by the noise and by the standard
            # error of the replicate mean: both go into the stated uncertainty.
            u = (NOISE_DEG ** 2 + (sem[w] or 0.0) ** 2) ** 0.5
            f.write(f'angle_deg,deg,EP,{w},pseudo-2D heap,{v:.4g},{u:.3g},{ok[w]},'
                    f'synthetic,"{recipe}"\n')
    json.dump({"gamma_J_m2": {str(w): gamma(w) for w in LEVELS},
               "noise_free_angle_deg": {str(w): noise_free[w] for w in LEVELS},
               "run_statuses": {str(w): statuses[w] for w in LEVELS},
               "replicate_mean_sem_deg": {str(w): sem[w] for w in LEVELS},
               "replicates_with_an_angle": {str(w): ok[w] for w in LEVELS},
               "rolling_friction_EP_EP": ROLLING, "fidelity": FIDELITY, "recipe": recipe},
              open(os.path.join(OUT, "truth.json"), "w"), indent=2)


if __name__ == "__main__":
    main()
