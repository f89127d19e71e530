#!/usr/bin/env python3
"""The calibrated clumps through the segregation funnel: which orifice meters them, and does
coating change the heap there?

Takes the scenario files a clumps workflow wrote (`demcal reproduce
datasets/alizadeh2018/workflow_clumps.json --out WF`: WF/segregation/{uncoated,coated,excessive}/
experiment.json, carrying the calibrated shapes and Γ) and runs each arm as one quick heap per
seed (`demcal experiment segregation FILE --quick --replicates 1 --threads 1`, the seed in FILE's
"seed", under `nice -n 5`, JOBS at a time, default 2). An arm is SCENARIO@ORIFICE_MM[xSIZE]: the
scenario's file with the funnel's orifice fixed at ORIFICE_MM (the fidelity rule off), at the
file's quick fidelity (size x5) or with its size scale replaced by SIZE, e.g. uncoated@15.45 or
uncoated@14.95x4. Seeds are paired across arms (one seed pours one feed). Resumable: a run whose
result.json exists is skipped. Writes OUT/runs.csv (one row per heap: angle, funnel, EP's
segregation and the paper's mechanism observables), OUT/arms.csv (mean ± sem per arm) and
OUT/paired.csv (each arm minus the first, seed by seed); `--summary-only` just rewrites them.
Reading: docs/experiments/segregation_funnel.md.

  python3 bench/clump_funnel.py build/apps/demcal WF OUT --arms uncoated@15.45,coated@15.45 \
      [--seeds 2018,2019,2020] [--jobs 2] [--rolling-friction EP-BP=0.25 ...]
"""
import argparse
import csv
import json
import os
from concurrent.futures import ThreadPoolExecutor

from heap_runs import mean_sem, read_result, run_quick, set_pair, write_tables

SCENARIOS = ("uncoated", "coated", "excessive")
KEYS = ["angle_deg", "discharge_time_s", "funnel_mass_flow_kg_s", "ep_cov_3d", "ep_cov_3d_floor",
        "ep_s_n_3d", "ep_landing_depth_m", "ep_after_impact_J_kg", "ep_major_contacts",
        "ep_axis_offset", "cpu_s"]


def parse_arm(arm):
    scenario, _, rest = arm.partition("@")
    mm, _, size = rest.partition("x")
    try:
        if scenario not in SCENARIOS:
            raise ValueError
        return scenario, float(mm), float(size) if size else None
    except ValueError:
        raise SystemExit(f"arm {arm!r}: expected SCENARIO@ORIFICE_MM[xSIZE_SCALE] with SCENARIO "
                         f"in {SCENARIOS}")


def variant(workflow_out, arm, seed, rolling=()):
    scenario, mm, size = parse_arm(arm)
    exp = json.load(open(os.path.join(workflow_out, "segregation", scenario, "experiment.json")))
    exp["description"] = (f"bench/clump_funnel.py arm {arm}: the clumps workflow's {scenario} "
                          f"scenario with a fixed {mm} mm orifice. " + exp.get("description", ""))
    exp["seed"] = seed
    funnel = exp["segregation"]["funnel"]
    funnel.pop("effective_orifice_diameter_m", None)
    funnel.pop("beverloo_k", None)
    funnel["orifice_diameter_m"] = mm / 1000
    if size:
        exp["quick_fidelity"]["size_scale"] = size
    for pair in rolling:  # "A-B=VALUE": that pair's rolling friction
        names, _, value = pair.partition("=")
        a, _, b = names.partition("-")
        set_pair(exp, a, b, "rolling_friction", float(value))
        exp["description"] += f" Rolling friction {a}-{b} set to {value}."
    return exp


def run_one(demcal, workflow_out, out, arm, seed, rolling=()):
    d = os.path.join(out, arm, f"s{seed}")
    if os.path.exists(os.path.join(d, "result.json")):
        return
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "experiment.json")
    json.dump(variant(workflow_out, arm, seed, rolling), open(path, "w"), indent=1)
    run_quick(demcal, "segregation", path, d)


def rows_of(out, arm, seed):
    res, cpu = read_result(os.path.join(out, arm, f"s{seed}"))
    if not res:
        return []
    ep = next(s for s in res["species"] if s["species"] == "EP")
    mech = res.get("mechanism", {})
    r = res["runs"][0]
    m = lambda x: x.get("mean", float("nan")) if isinstance(x, dict) else float("nan")
    nan_if_none = lambda v: float("nan") if v is None else v
    return [{"arm": arm, "seed": seed, "status": r["status"],
             "angle_deg": nan_if_none(r.get("mixture_angle_deg")),
             "discharge_time_s": nan_if_none(r.get("discharge_time_s")),
             "funnel_regime": r.get("funnel_regime"),
             "funnel_mass_flow_kg_s": nan_if_none(r.get("funnel_mass_flow_kg_s")),
             "ep_grains": r["heap_grains_per_species"][2],
             "ep_cov_3d": nan_if_none(m(ep["cov_3d"])),
             "ep_cov_3d_floor": nan_if_none(m(ep["cov_3d_floor"])),
             "ep_s_n_3d": nan_if_none(m(ep["s_n_3d"])),
             "ep_landing_depth_m": nan_if_none(m(mech.get("tracked_landing_depth_m"))),
             "ep_after_impact_J_kg": nan_if_none(m(mech.get("tracked_after_impact_specific_kinetic_J_kg"))),
             "ep_major_contacts": nan_if_none(m(mech.get("tracked_major_contacts_per_grain"))),
             "ep_axis_offset": nan_if_none(m(mech.get("tracked_axis_offset_fraction"))),
             "settle_time_s": r.get("settle_time_s"), "cpu_s": cpu}]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("demcal")
    ap.add_argument("workflow_out")
    ap.add_argument("out")
    ap.add_argument("--arms", required=True)
    ap.add_argument("--seeds", default="2018,2019,2020")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--rolling-friction", action="append", default=[], metavar="A-B=VALUE",
                    help="set a pair's rolling friction in every arm (repeatable; use another OUT)")
    ap.add_argument("--summary-only", action="store_true")
    a = ap.parse_args()
    arms, seeds = a.arms.split(","), [int(s) for s in a.seeds.split(",")]
    for arm in arms:
        parse_arm(arm)
    if not a.summary_only:
        with ThreadPoolExecutor(a.jobs) as pool:
            for f in [pool.submit(run_one, a.demcal, a.workflow_out, a.out, arm, s,
                                  a.rolling_friction)
                      for s in seeds for arm in arms]:
                f.result()
    rows = [r for arm in arms for s in seeds for r in rows_of(a.out, arm, s)]
    if rows:
        write_tables(a.out, rows, arms, KEYS)
        write_paired(a.out, rows, arms)


def write_paired(out, rows, arms):
    """OUT/paired.csv: for each arm after the first, the per-seed difference arm − first arm of
    every key (seeds where both finished ok), mean ± sem and z = mean / sem; one seed pours
    one feed in every arm, so the feed's own scatter drops out of the difference."""
    by = {(r["arm"], r["seed"]): r for r in rows if r["status"] == "ok"}
    with open(os.path.join(out, "paired.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["arm", "minus", "seeds", "key", "difference", "sem", "z"])
        for arm in arms[1:]:
            seeds = sorted(s for (a, s) in by if a == arm and (arms[0], s) in by)
            for k in KEYS:
                m, e = mean_sem([by[(arm, s)][k] - by[(arms[0], s)][k] for s in seeds])
                w.writerow([arm, arms[0], len(seeds), k, f"{m:.4g}", f"{e:.4g}",
                            f"{m / e:.3g}" if e > 0 else "nan"])
    print(open(os.path.join(out, "paired.csv")).read())


if __name__ == "__main__":
    main()
