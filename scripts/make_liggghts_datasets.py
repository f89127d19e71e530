#!/usr/bin/env python3
"""OTHER-ENGINE data: cross-engine datasets for `demcal diagnose`, made with Debian's LIGGGHTS 3.8
(/usr/bin/liggghts) in the scene the diagnosis examples simulate at --quick. LIGGGHTS-made, never
measured; demcal did not make them.

  python3 scripts/make_liggghts_datasets.py [--cases control,adhesion,...] [--replicates 4]
Held-out datasets (other strengths and seeds, never in the repository; scripts/liggghts_heldout.py):
  python3 scripts/make_liggghts_datasets.py --out /tmp/heldout --seed-base 300000 --noise-seed 777 \
      --cases wide_psd --change 'diameter_range_m=[0.00025,0.0006]' --name wide_psd_narrower
 --out DIR       case folders there; outside datasets/liggghts_crossengine also DIR/studies/
                 crossengine_<name>.json (absolute paths) and its _cdt_relative variant
 --seed-base N, --noise-seed N   SEED_BASE and NOISE_SEED below
 --change KEY=JSON   override one key the case's hidden change already has (repeatable); the sign
                 in truth.json follows the value against the base for cdt mur_pp and mu_pw
 --name NAME     the case folder's name (one case)
 Any of these but --out needs an --out outside the bundled folder. The defaults reproduce the
 bundled tables bit for bit.
The engines side by side where their laws agree, and the heap metric's port:
scripts/liggghts_agreement.py.

Recipe (datasets/liggghts_crossengine/README.md):
 1. The model of examples/diagnose/aor_bp_heap.json (rig 1: the 16 mm slot box),
    aor_bp_heap_narrow.json (rig 2: the same heap in a 12.5 mm box), discharge_bp_small.json
    (the funnel) and discharge_bp_narrow.json (rig 3: a narrow, steep funnel), at their quick
    fidelity (sizes x5, stiffness x0.01), written as LIGGGHTS decks
    (scripts/liggghts_decks.py). Base: BP spheres, BP-BP sliding friction 0.5 (the twins' value),
    rolling friction by LIGGGHTS' own constant-torque law `cdt` at 0.20 between grains (demcal's
    0.10 at the torque-equivalent coefficient: LIGGGHTS multiplies by R* = R/2, demcal by R) and
    0.055 against the walls (R* = R there).
 2. One effect hidden per case (CASES below), the rest as the base.
 3. Runs one at a time under `nice -n 10`, REPLICATES replicates with prime seeds from SEED_BASE.
    Where the case has no adhesion the coating changes nothing in the model: the heap is simulated
    once per rig and its mean is the noise-free value of every coating row (the demcal twins used
    the same seeds at every level too); with adhesion each level is simulated.
 4. Observables measured by demcal's own definitions, ported (scripts/liggghts_measure.py).
 5. Measurement noise as the demcal twins (scripts/make_diagnose_twins.py): a seeded Gaussian draw
    (random.Random(NOISE_SEED + case index)) of the stated uncertainty: 1.0 deg angle, 3 % heap
    height, 0.5 mm crest drop, 3 % discharge time and mass flow, 1 % bulk density.
Writes datasets/liggghts_crossengine/<case>/measurements.csv (provenance PROVENANCE, source naming
LIGGGHTS), runs.csv (every replicate, its status and CPU seconds) and truth.json (scoring only).
"""
import argparse, csv, json, math, os, random, resource, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liggghts_decks as decks  # noqa: E402
import liggghts_heldout as heldout  # noqa: E402
import liggghts_measure as measure  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "datasets", "liggghts_crossengine")
LIGGGHTS = "/usr/bin/liggghts"
VERSION = "LIGGGHTS-PUBLIC 3.8.0 (Debian liggghts package)"
# Values made by another engine: the table reader's provenance for them (datasets/README.md).
PROVENANCE = "simulated:liggghts-3.8"
SEED_BASE, REPLICATES, NOISE_SEED = 100000, 4, 200
COATINGS = [0.0, 1.5, 3.0]
RIGS = {"slot": ("aor_bp_heap.json", "pseudo-2D heap"),
        "narrow": ("aor_bp_heap_narrow.json", "narrow pseudo-2D heap")}
RIG2_COATINGS = [0.0, 3.0]
# Funnels, all at 0 wt%: name -> (experiment file, test label, seed condition). The narrow funnel
# (rig 3) was added later on condition 6, which no earlier rig used, and its rows are written
# after the first funnel's, so the earlier rows, their seeds and their noise draws are unchanged.
FUNNELS = {"funnel": ("discharge_bp_small.json", "funnel", 9),
           "narrow_funnel": ("discharge_bp_narrow.json", "narrow funnel", 6)}
BASE = {"sliding_friction": 0.5, "rolling": "cdt", "mur_pp": 0.20, "mur_pw": 0.055}
# case -> (library effect the diagnosis should name, LIGGGHTS change, sign). Strengths: clear
# changes of the heap at quick fidelity, not tuned to any diagnosis result.
CASES = {
    "control": (None, {}, None),
    "adhesion": ("jkr_adhesion", {"ced_J_m3_per_wt_pct": 7.5e3}, "+"),
    "rolling_strong": ("rolling_resistance", {"rolling": "epsd2", "mur_pp": 0.3}, "+"),
    "elongated": ("particle_shape", {"clump": 2.0}, "+"),
    "wall_friction_high": ("wall_friction", {"mu_pw": 0.9}, "+"),
    "wide_psd": ("size_polydispersity", {"diameter_range_m": [0.000200, 0.000725]}, "+"),
    "rolling_low": ("rolling_resistance", {"mur_pp": 0.05}, "-"),
}
NOISE = {"angle_deg": ("deg", lambda v: 1.0), "heap_height_m": ("m", lambda v: 0.03 * v),
         "crest_drop_m": ("m", lambda v: 0.0005), "discharge_time_s": ("s", lambda v: 0.03 * v),
         "mass_flow_kg_s": ("kg/s", lambda v: 0.03 * v), "bulk_density_kg_m3": ("kg/m3", lambda v: 0.01 * v)}
HEAP_OBS = ("angle_deg", "heap_height_m", "crest_drop_m")
FUNNEL_OBS = ("discharge_time_s", "mass_flow_kg_s", "bulk_density_kg_m3")


def experiment(name):
    return json.load(open(os.path.join(ROOT, "examples", "diagnose", name)))


def model_for(exp, case, coating, rolling_off=False, change=None):
    q = exp["quick_fidelity"]
    m = decks.Model(exp, q["size_scale"], q["stiffness_scale"])
    if change is None:
        change = CASES[case][1] if case else {}
    m.mu_pp = BASE["sliding_friction"]
    m.rolling, m.mur_pp, m.mur_pw = change.get("rolling", BASE["rolling"]), change.get("mur_pp", BASE["mur_pp"]), BASE["mur_pw"]
    if rolling_off:
        m.rolling, m.mur_pp, m.mur_pw = None, 0.0, 0.0
    m.mu_pw = change.get("mu_pw", m.mu_pw)
    m.ced_J_m3 = change.get("ced_J_m3_per_wt_pct", 0.0) * coating
    m.clump = change.get("clump")
    if "diameter_range_m" in change:
        m.d_range = [q["size_scale"] * d for d in change["diameter_range_m"]]
    return m


def seeds(case_index, cond, rep, seed_base=SEED_BASE):
    return decks.primes_from(seed_base + 1000 * (100 * case_index + 10 * cond + rep), 8)


RUN_LIMIT_S = 1800  # wall clock per run on a loaded machine; LIGGGHTS can hang after an ERROR


def run_deck(deck, work):
    path = os.path.join(work, "in.deck")
    open(path, "w").write(deck)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = time.time()
    try:
        subprocess.run(["nice", "-n", "10", LIGGGHTS, "-in", "in.deck", "-log", "log.deck", "-echo", "none"],
                       cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT, check=False,
                       timeout=RUN_LIMIT_S)
    except subprocess.TimeoutExpired:
        pass  # the missing dump or outflow record reports it
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    log = open(os.path.join(work, "log.deck"), errors="replace").read() if os.path.exists(os.path.join(work, "log.deck")) else ""
    return log, cpu, time.time() - wall


def heap_run(m, aor, sd):
    with tempfile.TemporaryDirectory() as work:
        deck = decks.heap_deck(m, aor, sd, random.Random(sd[0]), "heap.dump")
        log, cpu, wall = run_deck(deck, work)
        dump = os.path.join(work, "heap.dump")
        if "ERROR" in log or not os.path.exists(dump):
            return {"status": "liggghts_error", "message": _error(log), "cpu_s": cpu, "wall_s": wall}
        rows = measure.read_dump(dump)
    base = [r for r in rows if r["type"] == 2]
    heap = [(r["x"], r["z"], r["radius"]) for r in rows if r["type"] == 1]
    out = measure.slot_heap(heap, 1.125 * m.base_d) if base else {"ok": False, "message": "no base"}
    status = "not_settled" if "DEMCAL_STATUS not_settled" in log else "ok" if out["ok"] else "no_angle"
    return {"status": status, "message": out.get("message", ""), "cpu_s": cpu, "wall_s": wall,
            "particles": len(heap), **{k: out.get(k) for k in HEAP_OBS}}


def funnel_run(m, dis, sd):
    with tempfile.TemporaryDirectory() as work:
        deck = decks.funnel_deck(m, dis, sd, os.path.join(work, "hopper.stl"), "outflow.txt", "fill.dump")
        log, cpu, wall = run_deck(deck, work)
        try:
            rows = measure.read_dump(os.path.join(work, "fill.dump"))
            samples = [tuple(map(float, l.split())) for l in open(os.path.join(work, "outflow.txt"))
                       if l.strip() and not l.startswith("t")]
        except OSError:
            return {"status": "liggghts_error", "message": _error(log), "cpu_s": cpu, "wall_s": wall}
    # LIGGGHTS gives a multisphere grain's member atoms their spheres' masses, which overlap: the
    # atoms' masses are scaled so that they sum to the inserted feed mass (the grains' masses).
    atoms_kg = sum(r["mass"] for r in rows)
    scale = dis["feed"]["mass_kg"] / atoms_kg if m.clump and atoms_kg > 0 else 1.0
    fill = scale * sum(r["mass"] for r in rows if r["z"] > 0)
    t0 = samples[0][0] if samples else 0.0
    flow = measure.discharge([(t - t0, scale * x) for t, x in samples], fill)
    grains = [(r["x"], r["y"], r["z"], scale * r["mass"]) for r in rows]
    dmax = m.d_range[1]
    status = ("jammed" if "DEMCAL_STATUS jammed" in log else "not_empty" if "DEMCAL_STATUS not_empty" in log
              else "not_settled" if "DEMCAL_STATUS not_settled" in log else "ok" if flow["ok"] else "no_metrics")
    left = fill - scale * (samples[-1][1] if samples else 0.0)
    message = (f"no outflow for {dis['stall_s']} s with {left:.3g} kg ({100 * left / fill:.0f}% of the fill) "
               "left in the hopper" if status == "jammed" else flow.get("message", ""))
    res = {"status": status, "message": message, "cpu_s": cpu, "wall_s": wall, "particles": len(rows),
           "bulk_density_kg_m3": measure.bulk_density(grains, dis["hopper"], dmax)}
    if status == "ok":
        res.update({k: flow[k] for k in ("discharge_time_s", "mass_flow_kg_s")})
    return res


def _error(log):
    return next((l for l in log.splitlines() if "ERROR" in l), "LIGGGHTS wrote no output")


def mean_sd(runs, key):
    v = [r[key] for r in runs if r["status"] == "ok" and r.get(key) is not None]
    if not v:
        return None, None, 0
    mu = sum(v) / len(v)
    return mu, (math.sqrt(sum((x - mu) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else None), len(v)


def simulate(spec, replicates, log):
    """Every run of a case: list of (rig or 'funnel', coating, replicate, result)."""
    case, change = spec["case"], spec["change"]
    ci = list(CASES).index(case)
    adhesive = "ced_J_m3_per_wt_pct" in change
    runs = []
    for r_i, (rig, (name, _)) in enumerate(RIGS.items()):
        exp = experiment(name)
        levels = (COATINGS if rig == "slot" else RIG2_COATINGS) if adhesive else [None]
        for w in levels:
            for rep in range(replicates):
                res = heap_run(model_for(exp, case, w or 0.0, change=change), exp["aor"],
                               seeds(ci, 3 * r_i + round((w or 0) / 1.5), rep, spec["seed_base"]))
                runs.append((rig, w, rep, res))
                log(f"{case} {rig} w={w} r{rep}: {res['status']} {res.get('angle_deg')} cpu {res['cpu_s']:.1f} s")
    for rig, (name, _, cond) in FUNNELS.items():
        exp = experiment(name)
        for rep in range(replicates):
            res = funnel_run(model_for(exp, case, 0.0, change=change), exp["discharge"],
                             seeds(ci, cond, rep, spec["seed_base"]))
            runs.append((rig, 0.0, rep, res))
            log(f"{case} {rig} r{rep}: {res['status']} {res.get('discharge_time_s')} cpu {res['cpu_s']:.1f} s")
    return runs


def write_case(spec, runs, replicates, provenance):
    case, ci = spec["name"], list(CASES).index(spec["case"])
    rng = random.Random(spec["noise_seed"] + ci)
    out_dir = os.path.join(spec["out"], case)
    os.makedirs(out_dir, exist_ok=True)
    recipe = (f"LIGGGHTS-MADE (other engine, not measured): {VERSION}, quick-fidelity scene of examples/diagnose, "
              f"case {case}; mean of {replicates} replicates plus seeded Gaussian noise of the stated uncertainty; "
              f"scripts/make_liggghts_datasets.py")
    if spec["variant"]:
        recipe += (f"; HELD-OUT variant of case {spec['case']} (seed base {spec['seed_base']}, noise seed "
                   f"{spec['noise_seed']}; its truth.json gives the change)")
    rows, noise_free, notes = [], {}, []
    for rig, (name, test) in RIGS.items():
        depth = experiment(name)["aor"]["depth_m"]
        for w in (COATINGS if rig == "slot" else RIG2_COATINGS):
            group = [r for g, lv, _, r in runs if g == rig and (lv == w or lv is None)]
            for obs in HEAP_OBS:
                rows.append((obs, w, test, depth, mean_sd(group, obs), group))
    for rig, (_, test, _) in FUNNELS.items():
        group = [r for g, _, _, r in runs if g == rig]
        for obs in FUNNEL_OBS:
            rows.append((obs, 0.0, test, None, mean_sd(group, obs), group))
    with open(os.path.join(out_dir, "measurements.csv"), "w") as f:
        f.write("observable,unit,material,coating_PEG_wt_pct,test,box_depth_m,value,uncertainty,repeats,provenance,source\n")
        for obs, w, test, depth, (mu, sd, n), group in rows:
            if mu is None:
                bad = sorted({r["status"] for r in group if r["status"] != "ok"})
                notes.append(f"{obs} at {w:g} wt% ({test}): no value, runs {', '.join(bad)}; row left out")
                continue
            unit, u = NOISE[obs][0], NOISE[obs][1](mu)
            noise_free[f"{obs}|{w:g}|{test}"] = {"mean": mu, "sd": sd, "n": n}
            dcol = "" if depth is None else f"{depth:g}"
            f.write(f'{obs},{unit},BP,{w:g},{test},{dcol},{mu + rng.gauss(0, u):.6g},{u:.3g},{n},{provenance},"{recipe}"\n')
    with open(os.path.join(out_dir, "runs.csv"), "w") as f:
        f.write("rig,coating_PEG_wt_pct,replicate,status,angle_deg,heap_height_m,crest_drop_m,discharge_time_s,"
                "mass_flow_kg_s,bulk_density_kg_m3,particles,cpu_s,wall_s,message\n")
        for g, w, rep, r in runs:
            vals = ",".join("" if r.get(k) is None else f"{r[k]:.6g}" for k in HEAP_OBS + FUNNEL_OBS)
            lv = "all" if w is None else f"{w:g}"
            f.write(f'{g},{lv},{rep},{r["status"]},{vals},{r.get("particles", "")},{r["cpu_s"]:.2f},{r["wall_s"]:.1f},"{r["message"]}"\n')
    truth = {"case": case, "engine": VERSION, "hidden_effect": CASES[spec["case"]][0], "sign": spec["sign"],
             "liggghts_change": spec["change"], "base": BASE, "noise_free": noise_free, "notes": notes,
             "recipe": recipe}
    if spec["held_out"]:
        truth.update({"made_from_case": spec["case"], "seed_base": spec["seed_base"],
                      "noise_seed": spec["noise_seed"],
                      "noise_rng_seed": spec["noise_seed"] + ci, "replicates": replicates})
    json.dump(truth, open(os.path.join(out_dir, "truth.json"), "w"), indent=2)
    for n in notes:
        print(f"{case}: {n}", file=sys.stderr)


def write_study(spec):
    """The twins' study (diagnose_none.json: mu_s fitted, its optimiser and replicates) over every row
    the case's table holds: both heaps and both funnels. Bundled cases: examples/diagnose/
    crossengine_<case>.json, paths relative to it; held-out ones: OUT/studies/crossengine_<name>.json
    with absolute paths (the study loader resolves a relative path against the study's folder), its
    matching-law variant (scripts/liggghts_matching_studies.py) and its variant with the rolling
    friction fitted (scripts/liggghts_rolling_fitted_studies.py)."""
    case, examples = spec["name"], os.path.join(ROOT, "examples", "diagnose")
    study = json.load(open(os.path.join(examples, "diagnose_none.json")))
    files = {test: name for name, test in RIGS.values()}
    files.update({test: name for name, test, _ in FUNNELS.values()})
    if spec["held_out"]:
        files = {test: os.path.join(examples, name) for test, name in files.items()}
    table = os.path.join(spec["out"], case, "measurements.csv")
    targets = []
    with open(table) as f:
        for row in csv.DictReader(f):
            w = float(row["coating_PEG_wt_pct"])
            targets.append({"experiment_file": files[row["test"]], "observable": row["observable"],
                            "measurement": {"material": "BP", "conditions": {
                                "coating_PEG_wt_pct": int(w) if w == int(w) else w, "test": row["test"]}}})
    where = (f"held-out case {case} in {spec['out']}" if spec["held_out"] else
             f"case {case} of datasets/liggghts_crossengine/")
    study["description"] = (f"Diagnosis on OTHER-ENGINE data: LIGGGHTS-made (not measured, not made by demcal), "
                            f"{where} (scripts/make_liggghts_datasets.py). "
                            "Base model as the twins' studies: BP spheres, BP-BP sliding friction fitted; rig 1 "
                            "(16 mm slot heap) at 0, 1.5 and 3 wt% PEG, rig 2 (12.5 mm slot heap) at 0 and 3 wt%, "
                            "the funnel and rig 3 (the narrow funnel: 4 g, 21 mm top, 12.5 mm orifice, 10 degree "
                            "half-angle) at 0 wt%. Run with --quick, the fidelity the data were made at.")
    study["measurements"] = table if spec["held_out"] else f"../../datasets/liggghts_crossengine/{case}/measurements.csv"
    study["targets"] = targets
    folder = os.path.join(spec["out"], "studies") if spec["held_out"] else examples
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, f"crossengine_{case}.json")
    json.dump(study, open(path, "w"), indent=2)
    open(path, "a").write("\n")
    if spec["held_out"]:
        # Both import this module: imported here, when used.
        import liggghts_matching_studies as matching
        import liggghts_rolling_fitted_studies as rolling_fitted
        matching.write_study(case, folder, where)
        rolling_fitted.write_study(case, folder, where)


def cases_from_arguments(description):
    """The --cases a study-writing script was given (default: every bundled case), each known."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--cases", default=",".join(CASES))
    cases = ap.parse_args().cases.split(",")
    for case in cases:
        if case not in CASES:
            sys.exit(f"--cases: unknown case '{case}' (known: {', '.join(CASES)})")
    return cases


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--replicates", type=int, default=REPLICATES)
    ap.add_argument("--provenance", default=PROVENANCE)
    heldout.add_arguments(ap, OUT, SEED_BASE, NOISE_SEED)
    a = ap.parse_args()
    log = lambda s: print(time.strftime("%H:%M:%S ") + s, file=sys.stderr, flush=True)  # noqa: E731
    wall = decks.Model(experiment(RIGS["slot"][0]), 1.0, 1.0).mu_pw  # every rig's: 0.42
    for spec in heldout.specs(a, CASES, {**BASE, "mu_pw": wall}, OUT, SEED_BASE, NOISE_SEED):
        runs = simulate(spec, a.replicates, log)
        write_case(spec, runs, a.replicates, a.provenance)
        write_study(spec)
        log(f"{spec['name']}: written to {os.path.join(spec['out'], spec['name'])}")


if __name__ == "__main__":
    main()
