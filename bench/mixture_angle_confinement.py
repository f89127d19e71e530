#!/usr/bin/env python3
"""Is the ternary heap's excess angle an artefact of the 16 mm slab at size x5?

Writes variant experiment files from examples/segregation_paper.json and runs each as one quick
heap per seed (`demcal experiment segregation FILE --quick --replicates 1 --threads 1`, the seed
in FILE's "seed", under `nice -n 5`, JOBS at a time, default 2), the seeds paired across arms
(one seed pours one feed). Results and reading: docs/experiments/segregation_angle.md. Arms (spheres: the main job's calibrated self-pair rolling friction BP 0.34, TAED 0.19,
EP 0.25, dissimilar pairs as in the file; clumps: the current calibrated shapes, BP a = 3.044
n = 4, TAED 2.856 n = 5, EP 2.280 n = 3, Table 1's rolling friction as in the file):
  sphere_base     the file as it is (16 mm slab, Perspex front/back)
  sphere_smooth   front/back walls frictionless: the box (faces, floor under the glued base) is a
                  copy of Perspex whose pairs with every species have sliding and rolling
                  friction 0; the funnel stays Perspex (`funnel_material`; the faces still cut
                  the funnel, so its flow changes a little)
  sphere_deep     the slab 2x deeper (32 mm) with feed mass and rate 2x, so the heap's cross-section
                  and height stay the same; a fixed 19 mm orifice for about 2x the flow
                  (Beverloo, open width x 2^0.4)
  sphere_bp       BP alone (feed 100 % BP, 30.85 g) in the file's box: the species in the mixture's
                  box, against its own repose box (examples/aor_bp.json); its funnel drains so
                  slowly that the heap did not settle in the file's 6 s (aor_bp_sphere_big instead)
  clump_base, clump_smooth   the same for the clumps
  clump_orifice16     the clumps through a 16 mm orifice, the widest circle the 16 mm slab holds
                      (the file's rule gives 15.5 mm at x5): does the funnel empty near 2.22 s?
and, for the comparison with the species' own repose box (examples/aor_bp.json at --quick, size x5,
4 heaps per seed; its quick step is 0.25 of the Rayleigh time, the heap file's 0.2):
  aor_bp_sphere, aor_bp_sphere_dt02   BP spheres at mu_r 0.34, step 0.25 / 0.2 of t_R
  aor_bp_clump, aor_bp_clump_dt02     BP clumps (4 spheres, a = 3.044), step 0.25 / 0.2 of t_R
  aor_bp_sphere_smooth, aor_bp_clump_smooth  the *_dt02 arms with frictionless front/back walls
  aor_bp_sphere_big   the repose box grown to the heap's size: 30.85 g of BP spheres (mu_r 0.34,
                      step 0.2 of t_R) poured at 18.5 g/s from 0.1 m over a 40 mm feed into a
                      0.2 m wide box, no funnel (1 heap per seed)
  aor_bp_sphere_big_smooth  the same with frictionless front/back walls
  aor_bp_clump_big    the same grown box with the BP clumps (Table 1's mu_r 0.10)
  aor_bp_clump_big_half  the same poured at half the rate (9.25 g/s, about what the clump feed
                      inserted before f793d06)
Resumable: a run whose result.json exists is skipped. Writes OUT/runs.csv (one row per heap; angle_deg: the mixture angle, or the repose-box heap's angle) and
OUT/arms.csv (mean +- sem per arm) from every finished run; `--summary-only` just rewrites them.

  python3 bench/mixture_angle_confinement.py build/apps/demcal OUT [--arms a,b] [--seeds 2018,2019]
"""
import argparse
import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor

from heap_runs import read_result, run_quick, set_pair, write_tables

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLE = os.path.join(REPO, "examples", "segregation_paper.json")
SPHERE_MU_R = {"BP": 0.34, "TAED": 0.19, "EP": 0.25}  # docs/reproduce.md, stage 1 at size x3
CLUMPS = {"BP": (3.044, 4), "TAED": (2.856, 5), "EP": (2.280, 3)}  # docs/reproduce.md, Fig. 3
ARMS = ["sphere_base", "sphere_smooth", "sphere_deep", "sphere_bp", "clump_base", "clump_smooth",
        "clump_orifice16",
        "aor_bp_sphere", "aor_bp_sphere_dt02", "aor_bp_clump", "aor_bp_clump_dt02",
        "aor_bp_sphere_smooth", "aor_bp_sphere_big", "aor_bp_sphere_big_smooth",
        "aor_bp_clump_big", "aor_bp_clump_smooth", "aor_bp_clump_big_half"]
AOR_EXAMPLE = os.path.join(REPO, "examples", "aor_bp.json")
AOR_REPLICATES = 4


def smooth_walls(exp, section):
    # A frictionless twin of the wall material for the box; a funnel keeps the real one.
    wall = section["wall_material"]
    twin = wall + "_frictionless"
    exp["materials"].append(dict(next(m for m in exp["materials"] if m["name"] == wall), name=twin))
    for p in list(exp["interactions"]["pairs"]):
        if wall in p["materials"] and p["materials"] != [wall, wall]:
            other = p["materials"][0] if p["materials"][1] == wall else p["materials"][1]
            exp["interactions"]["pairs"].append(
                {"materials": [other, twin], "sliding_friction": 0.0, "rolling_friction": 0.0,
                 "restitution": p["restitution"]})
    section["wall_material"] = twin
    if "funnel" in section:
        section["funnel_material"] = wall


def aor_variant(arm):
    exp = json.load(open(AOR_EXAMPLE))
    exp["description"] = f"bench/mixture_angle_confinement.py arm {arm}, from examples/aor_bp.json"
    if "sphere" in arm:
        exp["interactions"]["default"]["rolling_friction"] = SPHERE_MU_R["BP"]
    else:
        a, n = CLUMPS["BP"]
        exp["species"][0]["clump"] = {"ellipsoid": {"semi_axes": [a, 1, 1], "sphere_count": n}}
    if arm.endswith("dt02") or "big" in arm or arm.endswith("smooth"):
        exp["quick_fidelity"]["rayleigh_fraction"] = 0.2
    if "big" in arm:
        seg = json.load(open(EXAMPLE))["segregation"]
        a = exp["aor"]
        a["feed"]["mass_kg"] = seg["feed"]["mass_kg"]
        for k in ("width_m", "pour_height_m", "feed_width_m"):
            a[k] = seg[k]
        a["settle"]["max_time_s"] = seg["settle"]["max_time_s"]
    if arm.endswith("_half"):
        exp["aor"]["feed"]["mass_rate_kg_s"] /= 2
    if arm.endswith("smooth"):
        smooth_walls(exp, exp["aor"])
    return exp


def variant(arm):
    if arm.startswith("aor"):
        return aor_variant(arm)
    exp = json.load(open(EXAMPLE))
    exp["description"] = f"bench/mixture_angle_confinement.py arm {arm}, from examples/segregation_paper.json"
    seg = exp["segregation"]
    if arm.startswith("sphere"):
        for name, mu in SPHERE_MU_R.items():
            set_pair(exp, name, name, "rolling_friction", mu)
    else:
        for s in exp["species"]:
            a, n = CLUMPS[s["name"]]
            s["clump"] = {"ellipsoid": {"semi_axes": [a, 1, 1], "sphere_count": n}}
    if arm.endswith("smooth"):
        smooth_walls(exp, seg)
    if arm == "clump_orifice16":
        f = seg["funnel"]
        f.pop("effective_orifice_diameter_m")
        f.pop("beverloo_k")
        f["orifice_diameter_m"] = 0.016
    if arm == "sphere_deep":
        seg["depth_m"] = 2 * seg["depth_m"]
        seg["feed"]["mass_kg"] = 2 * seg["feed"]["mass_kg"]
        seg["feed"]["mass_rate_kg_s"] = 2 * seg["feed"]["mass_rate_kg_s"]
        f = seg["funnel"]
        f.pop("effective_orifice_diameter_m")
        f.pop("beverloo_k")
        f["orifice_diameter_m"] = 0.019
    if arm == "sphere_bp":
        seg["feed"]["components"] = [{"species": "BP", "mass_fraction": 1.0}]
        seg["tracking"]["species"] = "BP"
    return exp


def run_one(demcal, out, arm, seed):
    d = os.path.join(out, arm, f"s{seed}")
    if os.path.exists(os.path.join(d, "result.json")):
        return
    os.makedirs(d, exist_ok=True)
    aor = arm.startswith("aor")
    run_quick(demcal, "aor" if aor else "segregation",
              os.path.join(out, "files", f"{arm}_s{seed}.json"), d,
              AOR_REPLICATES if aor and "big" not in arm else 1)


def rows_of(out, arm, seed):
    res, cpu = read_result(os.path.join(out, arm, f"s{seed}"))
    return [row(arm, seed, r, cpu) for r in res["runs"]] if res else []


def row(arm, seed, r, cpu):
    g = lambda k: r.get(k, float("nan"))
    angle = g("angle_deg") if arm.startswith("aor") else g("mixture_angle_deg")
    return {"arm": arm, "seed": seed, "replicate": g("replicate"), "status": g("status"),
            "angle_deg": angle, "flank_spread_deg": g("flank_spread_deg"),
            "discharge_time_s": g("discharge_time_s"), "funnel_regime": g("funnel_regime"),
            "funnel_mass_flow_kg_s": g("funnel_mass_flow_kg_s"),
            "funnel_orifice_diameter_m": g("funnel_orifice_diameter_m"),
            "heap_height_m": g("heap_height_m"), "heap_base_width_m": g("heap_base_width_m"),
            "particles": g("particles"), "settle_time_s": g("settle_time_s"), "cpu_s": cpu}


def summarise(out, arms, seeds):
    rows = [r for a in arms for s in seeds for r in rows_of(out, a, s)]
    if not rows:
        return
    write_tables(out, rows, arms, ["angle_deg", "discharge_time_s", "funnel_mass_flow_kg_s",
                                   "heap_height_m", "cpu_s"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("demcal")
    ap.add_argument("out")
    ap.add_argument("--arms", default="sphere_base,sphere_smooth,sphere_deep")
    ap.add_argument("--seeds", default="2018,2019,2020")
    ap.add_argument("--summary-only", action="store_true")
    a = ap.parse_args()
    arms, seeds = a.arms.split(","), [int(s) for s in a.seeds.split(",")]
    unknown = [x for x in arms if x not in ARMS]
    if unknown:
        sys.exit(f"unknown arm(s) {unknown}; known: {ARMS}")
    out = os.path.abspath(a.out)
    if not a.summary_only:
        os.makedirs(os.path.join(out, "files"), exist_ok=True)
        for arm in arms:
            for seed in seeds:
                exp = dict(variant(arm), seed=seed)
                json.dump(exp, open(os.path.join(out, "files", f"{arm}_s{seed}.json"), "w"), indent=1)
        # Seed-major order: every arm gets its first seed before any arm gets its second.
        jobs = [(arm, s) for s in seeds for arm in arms]
        with ThreadPoolExecutor(int(os.environ.get("JOBS", "2"))) as pool:
            list(pool.map(lambda j: run_one(os.path.abspath(a.demcal), out, *j), jobs))
    summarise(out, arms, seeds)


if __name__ == "__main__":
    main()
