#!/usr/bin/env python3
"""SYNTHETIC data: the five datasets of the discrepancy workflow (`demcal diagnose`, docs/diagnose.md).

Recipe (re-runnable: `python3 scripts/make_diagnose_twins.py BUILD_DIR [CASE ...]`):
 1. The model of examples/diagnose/aor_bp_heap.json and examples/diagnose/discharge_bp_small.json
    (BP of Alizadeh et al. 2018 as spheres, BP-BP sliding friction set to 0.5, rolling friction
    0.10) with ONE effect hidden from the base model per case (TRUTH below; `none` hides nothing).
 2. Conditions: the heap at PEG coating levels 0, 1.5 and 3 wt% (the coating matters only where
    the hidden effect is adhesion growing with the coating), the funnel at 0 wt%.
 3. `demcal experiment aor` / `discharge` at the files' quick fidelity, REPLICATES replicates with
    base seed SEED (not the studies' seed 2018: the "measurement" has its own packings); the
    means over the replicates that gave a value are the noise-free values.
 4. Measurement noise: each value plus a seeded Gaussian draw (random.Random(NOISE_SEED + case
    index)) of the stated uncertainty: 1.0 deg for the angle (a typical repose repeatability),
    3 % for heap height, 0.5 mm for the crest drop (a quarter of a quick-fidelity grain), 3 % for
    discharge time and mass flow, 1 % for bulk density.
Writes datasets/synthetic/diagnose_<case>/measurements.csv (provenance: synthetic) and the truth to
truth.json beside it, which only the scoring test reads (tests/diagnose/diagnose_twins_long_test.cc).
"""
import json, os, random, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SEED, REPLICATES, NOISE_SEED = 7001, 4, 100
BASE = {"sliding_friction": 0.5, "rolling_friction": 0.10}
COATINGS = [0.0, 1.5, 3.0]
ELONGATED = {"ellipsoid": {"semi_axes": [2, 1, 1], "sphere_count": 3}}
# case -> (hidden effect the diagnosis should name, how it changes the model, parameters for truth.json)
TRUTH = {
    "none": (None, {}),
    "adhesion_coating": ("jkr_adhesion", {"gamma_J_m2_per_wt_pct": 0.006}),
    "rolling_strong": ("rolling_resistance", {"rolling_friction": 0.40}),
    "elongated": ("particle_shape", {"clump": ELONGATED, "aspect_ratio": 2.0}),
    "wide_psd": ("size_polydispersity", {"diameter_range_m": [0.000200, 0.000725]}),
}
NOISE = {"angle_deg": ("deg", lambda v: 1.0), "heap_height_m": ("m", lambda v: 0.03 * v),
         "crest_drop_m": ("m", lambda v: 0.0005), "discharge_time_s": ("s", lambda v: 0.03 * v),
         "mass_flow_kg_s": ("kg/s", lambda v: 0.03 * v), "bulk_density_kg_m3": ("kg/m3", lambda v: 0.01 * v)}


def model_for(path, case, coating):
    model = json.load(open(os.path.join(ROOT, "examples", "diagnose", path)))
    model["seed"] = SEED
    model["interactions"]["default"].update(BASE)
    truth = TRUTH[case][1]
    bp = next(s for s in model["species"] if s["name"] == "BP")
    pair = {"materials": ["BP", "BP"], "restitution": model["interactions"]["default"]["restitution"], **BASE}
    if "gamma_J_m2_per_wt_pct" in truth:
        pair["interfacial_energy_J_m2"] = truth["gamma_J_m2_per_wt_pct"] * coating
    if "rolling_friction" in truth:
        pair["rolling_friction"] = truth["rolling_friction"]
    model["interactions"]["pairs"].append(pair)
    if "clump" in truth:
        bp["clump"] = truth["clump"]
    if "diameter_range_m" in truth:
        bp["diameter_range_m"] = truth["diameter_range_m"]
    return model


def run(demcal, kind, model, tmp, tag):
    scene = os.path.join(tmp, tag + ".json")
    json.dump(model, open(scene, "w"))
    out = os.path.join(tmp, tag + ".out")
    subprocess.run(["nice", "-n", "10", demcal, "experiment", kind, scene, "--out", out, "--quick", "--replicates",
                    str(REPLICATES), "--quiet"], check=False, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "result.json")))


def mean_of_runs(result, key):
    values = [r[key] for r in result["runs"] if r.get("status") == "ok" and r.get(key) is not None]
    return sum(values) / len(values) if values else None


def make(demcal, case, index):
    rng = random.Random(NOISE_SEED + index)
    rows, noise_free = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        for w in COATINGS:
            aor = run(demcal, "aor", model_for("aor_bp_heap.json", case, w), tmp, f"aor_{w}")
            for obs in ("angle_deg", "heap_height_m", "crest_drop_m"):
                rows.append((obs, w, "pseudo-2D heap", mean_of_runs(aor, obs)))
        dis = run(demcal, "discharge", model_for("discharge_bp_small.json", case, 0.0), tmp, "discharge")
        for obs in ("discharge_time_s", "mass_flow_kg_s", "bulk_density_kg_m3"):
            rows.append((obs, 0.0, "funnel", dis.get(obs)))
    recipe = (f"SYNTHETIC: demcal at quick fidelity, BP spheres (sliding 0.5, rolling 0.10) with a hidden effect "
              f"(case {case}; truth.json), mean of {REPLICATES} replicates (seed {SEED}) plus seeded Gaussian noise "
              f"of the stated uncertainty; scripts/make_diagnose_twins.py")
    out_dir = os.path.join(ROOT, "datasets", "synthetic", "diagnose_" + case)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "measurements.csv"), "w") as f:
        f.write("observable,unit,material,coating_PEG_wt_pct,test,value,uncertainty,repeats,provenance,source\n")
        for obs, w, test, value in rows:
            if value is None:
                print(f"{case}: {obs} at {w} wt% gave no value; row left out", file=sys.stderr)
                continue
            unit, u = NOISE[obs][0], NOISE[obs][1](value)
            noise_free[f"{obs}|{w}"] = value
            f.write(f'{obs},{unit},BP,{w:g},{test},{value + rng.gauss(0, u):.6g},{u:.3g},{REPLICATES},synthetic,"{recipe}"\n')
    json.dump({"case": case, "hidden_effect": TRUTH[case][0], "truth": TRUTH[case][1], "base": BASE,
               "noise_free": noise_free, "recipe": recipe}, open(os.path.join(out_dir, "truth.json"), "w"), indent=2)
    print(f"{case}: {len(rows)} rows -> {out_dir}", file=sys.stderr)


def main():
    demcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "apps", "demcal")
    cases = sys.argv[2:] or list(TRUTH)
    for case in cases:
        make(demcal, case, list(TRUTH).index(case))


if __name__ == "__main__":
    main()
