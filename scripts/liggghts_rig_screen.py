#!/usr/bin/env python3
"""OTHER-ENGINE screen: how far one hidden effect moves each observable of a candidate rig, in
LIGGGHTS runs of the cross-engine recipe (scripts/make_liggghts_datasets.py), before any rig is
added to the datasets. LIGGGHTS-made, never measured.

  python3 scripts/liggghts_rig_screen.py heap --set feed.mass_kg=0.01 [--replicates 4]
  python3 scripts/liggghts_rig_screen.py funnel --set hopper.cone_half_angle_deg=10 \
      --set hopper.orifice_diameter_m=0.0125 [--case wall_friction_high] [--condition 7]

The rig is the 12.5 mm slot heap (aor_bp_heap_narrow.json) or the 36 mm funnel
(discharge_bp_small.json) with the `--set` changes to its aor / discharge section. The control and
the case run `--replicates` times each on the recipe's seeds of `--condition` (pick one that no
dataset rig uses, so that the screen does not pick a rig on the seeds that make its data: the
datasets use 0-5, 6 and 9). Printed per observable: both means and single-run standard
deviations, the relative change and the change in units of the σ the dataset's rows would have,
σ = √(u² + sd²_case/R + sd²_control/R) with R = the datasets' REPLICATES (4) and u the stated
measurement uncertainty (datasets/liggghts_crossengine/README.md).
"""
import argparse, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_liggghts_datasets as mk  # noqa: E402

FILES = {"heap": ("aor_bp_heap_narrow.json", "aor", mk.HEAP_OBS),
         "funnel": ("discharge_bp_small.json", "discharge", mk.FUNNEL_OBS)}


def set_path(section, path, value):
    keys = path.split(".")
    for k in keys[:-1]:
        section = section[k]
    if keys[-1] not in section:
        sys.exit(f"--set: no key '{path}' in the section")
    section[keys[-1]] = value


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("rig", choices=FILES)
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE")
    ap.add_argument("--case", default="wall_friction_high")
    ap.add_argument("--replicates", type=int, default=mk.REPLICATES)
    ap.add_argument("--condition", type=int, default=7)
    a = ap.parse_args()
    name, key, observables = FILES[a.rig]
    exp = mk.experiment(name)
    for kv in a.set:
        k, v = kv.split("=", 1)
        set_path(exp[key], k, json.loads(v))
    stats = {}
    for case in ("control", a.case):
        ci = list(mk.CASES).index(case)
        runs = []
        for rep in range(a.replicates):
            sd = mk.seeds(ci, a.condition, rep)
            m = mk.model_for(exp, case, 0.0)
            r = mk.heap_run(m, exp[key], sd) if a.rig == "heap" else mk.funnel_run(m, exp[key], sd)
            runs.append(r)
            print(f"{case} r{rep}: {r['status']} " + " ".join(f"{k}={r.get(k)}" for k in observables)
                  + f" cpu {r['cpu_s']:.1f} s", file=sys.stderr, flush=True)
        stats[case] = {k: mk.mean_sd(runs, k) for k in observables}
    print(f"{a.rig} {' '.join(a.set)}: control vs {a.case}, {a.replicates} replicates, condition {a.condition}")
    for k in observables:
        (mc, sc, nc), (me, se, ne) = stats["control"][k], stats[a.case][k]
        if sc is None or se is None:
            print(f"  {k}: fewer than 2 good runs (control {nc}, case {ne})")
            continue
        u = mk.NOISE[k][1](mc)
        sigma = math.sqrt(u * u + (sc * sc + se * se) / mk.REPLICATES)
        print(f"  {k}: {mc:.4g} (sd {sc:.2g}, n {nc}) -> {me:.4g} (sd {se:.2g}, n {ne}): "
              f"{100 * (me - mc) / abs(mc):+.0f} %, {(me - mc) / sigma:+.1f} sigma")


if __name__ == "__main__":
    main()
