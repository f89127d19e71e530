#!/usr/bin/env python3
"""Does a factory pour the segregation heap's feed at its nominal rate? (size x5, quick fidelity)

Writes a demcal-scene/1 file with the feed of examples/segregation_paper.json at size x5 and
stiffness x0.01 (BP/TAED/EP, 20 g/s, 30.85 g) as one factory over the heap's feed region (40 x 16
mm, 6 TAED diameters = 30 mm tall, entered at rest: FeedEntrySpeed gives 0 for this feed), pouring
into free fall (no walls, a sink below), so that nothing but the region's capacity sets the rate.
Grains: spheres, or the calibrated clumps of bench/mixture_angle_confinement.py. Runs `demcal
simulate` and prints the factory's report and warnings. Reading: docs/experiments/segregation_angle.md.

  python3 bench/clump_feed_rate.py build/apps/demcal OUT [--grains clump|sphere] [--duration-s 1.0]
"""
import argparse
import json
import os
import subprocess

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLUMPS = {"BP": (3.044, 4), "TAED": (2.856, 5), "EP": (2.280, 3)}  # docs/reproduce.md, Fig. 3
SIZE_SCALE, STIFFNESS_SCALE = 5, 0.01  # the file's quick fidelity


def scene(grains, duration_s):
    e = json.load(open(os.path.join(REPO, "examples", "segregation_paper.json")))
    materials = [dict(m, shear_modulus_Pa=m["shear_modulus_Pa"] * STIFFNESS_SCALE) for m in e["materials"]]
    species = []
    for s in e["species"]:
        s = dict(s, diameter_range_m=[SIZE_SCALE * d for d in s["diameter_range_m"]])
        if grains == "clump":
            a, n = CLUMPS[s["name"]]
            s["clump"] = {"ellipsoid": {"semi_axes": [a, 1, 1], "sphere_count": n}}
        species.append(s)
    feed = e["segregation"]["feed"]
    height = 6 * max(s["diameter_range_m"][1] for s in species)  # FeedRegionHeight
    return {
        "format": "demcal-scene/1", "seed": 2018,
        "description": f"the x5 segregation feed ({grains}) poured into free fall",
        "materials": materials, "species": species,
        "interactions": {"default": e["interactions"]["default"]},
        "domain": {"min_m": [-0.01, -0.01, 0], "max_m": [0.05, 0.026, 0.14]},
        "gravity_m_s2": [0, 0, -9.81],
        "factories": [{"name": "feed",
                       "species": [{"name": c["species"], "mass_fraction": c["mass_fraction"]}
                                   for c in feed["components"]],
                       "region": {"min_m": [0, 0, 0.1], "max_m": [0.04, 0.016, 0.1 + height]},
                       "mass_rate_kg_s": feed["mass_rate_kg_s"], "total_mass_kg": feed["mass_kg"]}],
        "sinks": [{"name": "below", "shape": "plane", "point_m": [0, 0, 0.03], "normal": [0, 0, -1]}],
        "time": {"duration_s": duration_s, "rayleigh_fraction": 0.2},
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("demcal")
    ap.add_argument("out")
    ap.add_argument("--grains", choices=["clump", "sphere"], default="clump")
    ap.add_argument("--duration-s", type=float, default=1.0)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "scene.json")
    json.dump(scene(a.grains, a.duration_s), open(path, "w"), indent=1)
    subprocess.run(["nice", "-n", "5", a.demcal, "simulate", path, "--out", a.out, "--threads", "1",
                    "--quiet"], check=False)
    summary = json.load(open(os.path.join(a.out, "summary.json")))
    for f in summary["factories"]:
        print(f"{f['name']}: {f['inserted_mass_kg'] * 1e3:.2f} g of {f['requested_mass_kg'] * 1e3:.2f} g "
              f"requested in {f['active_time_s']:.3f} s ({f['achieved_rate_kg_s'] * 1e3:.2f} g/s, "
              f"nominal {f['requested_rate_kg_s'] * 1e3:.2f} g/s), {f['particles']} particles, "
              f"{f['full_batches']} full batches")
    for w in summary.get("factory_warnings", []):
        print("warning:", w)


if __name__ == "__main__":
    main()
