"""Engine agreement where the laws are the same, and the metric port's check:
  python3 scripts/liggghts_agreement.py --agreement BUILD_DIR [--agreement-rolling off|cdt]
                                        [--replicates N]
  python3 scripts/liggghts_agreement.py --check-port DEMCAL_AOR_OUT_DIR
It reads the datasets' recipe (scripts/make_liggghts_datasets.py) and writes beside its data.

Agreement, rolling off (default): no rolling resistance in either engine (demcal
`contact_model.rolling = "none"`, LIGGGHTS `gran model hertz tangential history`). Rolling cdt:
the same constant-torque law in both, LIGGGHTS `rolling_friction cdt` and demcal `cdt_relative`
(its port, docs/physics.md section 2.1), both at the datasets' base coefficients (0.20 between
grains, 0.055 against the walls). Either way BP-BP sliding friction 0.5 and everything else as the
diagnosis examples at quick fidelity; the rig-1 heap and the funnel, N replicates each with each
engine's own seeds. Per observable: offset = mean(LIGGGHTS) - mean(demcal) in units of the pooled
single-run scatter s (the replicates' standard deviation pooled over both engines), and the
offset's own standard error in those units, sqrt(1/n_L + 1/n_D). Written to
datasets/liggghts_crossengine/agreement.csv (rolling off) or agreement_cdt.csv (rolling cdt) and
printed as a Markdown table.
"""
import argparse, json, math, os, struct, subprocess, sys, tempfile, time

import make_liggghts_datasets as mk
import liggghts_measure as measure

DEMCAL_SEED = 7001


def _demcal(build, kind, exp, replicates, out):
    scene = out + ".json"
    json.dump(exp, open(scene, "w"))
    subprocess.run(["nice", "-n", "10", os.path.join(build, "apps", "demcal"), "experiment", kind, scene, "--out", out,
                    "--quick", "--replicates", str(replicates), "--quiet"], check=False, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "result.json")))["runs"]


def _rolling_off(exp):
    exp = json.loads(json.dumps(exp))
    exp["seed"] = DEMCAL_SEED
    exp["interactions"]["default"].update({"sliding_friction": mk.BASE["sliding_friction"], "rolling_friction": 0.0})
    for p in exp["interactions"]["pairs"]:
        p["rolling_friction"] = 0.0
    exp["contact_model"] = {"rolling": "none"}
    return exp


def _rolling_cdt(exp):
    """demcal's port of LIGGGHTS' cdt at the LIGGGHTS base's coefficients (no conversion needed)."""
    exp = json.loads(json.dumps(exp))
    exp["seed"] = DEMCAL_SEED
    exp["interactions"]["default"].update({"sliding_friction": mk.BASE["sliding_friction"],
                                           "rolling_friction": mk.BASE["mur_pp"]})
    for p in exp["interactions"]["pairs"]:
        p["rolling_friction"] = mk.BASE["mur_pw"]
    exp["contact_model"] = {"rolling": "cdt_relative"}
    return exp


def _stats(values):
    n = len(values)
    mu = sum(values) / n if n else float("nan")
    var = sum((x - mu) ** 2 for x in values) / (n - 1) if n > 1 else float("nan")
    return mu, var, n


def main(a, log):
    if a.check_port:
        return check_port(a.check_port, log)
    n = a.replicates
    off = a.agreement_rolling == "off"
    demcal_scene = _rolling_off if off else _rolling_cdt
    heap_exp, dis_exp = mk.experiment("aor_bp_heap.json"), mk.experiment("discharge_bp_small.json")
    lig = {"heap": [], "funnel": []}
    for rep in range(n):
        lig["heap"].append(mk.heap_run(mk.model_for(heap_exp, "control", 0.0, off), heap_exp["aor"], mk.seeds(90, 0, rep)))
        log(f"agreement LIGGGHTS heap r{rep}: {lig['heap'][-1]}")
    for rep in range(n):
        lig["funnel"].append(mk.funnel_run(mk.model_for(dis_exp, "control", 0.0, off), dis_exp["discharge"], mk.seeds(90, 9, rep)))
        log(f"agreement LIGGGHTS funnel r{rep}: {lig['funnel'][-1]}")
    with tempfile.TemporaryDirectory() as tmp:
        t = time.time()
        dem_heap = _demcal(a.agreement, "aor", demcal_scene(heap_exp), n, os.path.join(tmp, "aor"))
        dem_funnel = _demcal(a.agreement, "discharge", demcal_scene(dis_exp), n, os.path.join(tmp, "dis"))
        log(f"agreement demcal runs: {time.time() - t:.0f} s wall")
    table = []
    for obs, lruns, druns in [(o, lig["heap"], dem_heap) for o in mk.HEAP_OBS] + \
                             [(o, lig["funnel"], dem_funnel) for o in mk.FUNNEL_OBS]:
        lv = [r[obs] for r in lruns if r["status"] == "ok" and r.get(obs) is not None]
        dv = [r[obs] for r in druns if r.get("status") == "ok" and r.get(obs) is not None]
        ml, vl, nl = _stats(lv)
        md, vd, nd = _stats(dv)
        s = math.sqrt(((nl - 1) * vl + (nd - 1) * vd) / (nl + nd - 2)) if nl > 1 and nd > 1 else float("nan")
        table.append((obs, md, ml, s, (ml - md) / s, math.sqrt(1 / max(nl, 1) + 1 / max(nd, 1)), nl, nd))
    path = os.path.join(mk.OUT, "agreement.csv" if off else "agreement_cdt.csv")
    os.makedirs(mk.OUT, exist_ok=True)
    with open(path, "w") as f:
        f.write("observable,demcal_mean,liggghts_mean,single_run_scatter,offset_in_scatters,offset_sem_in_scatters,"
                "liggghts_runs,demcal_runs\n")
        for row in table:
            f.write(",".join(f"{x:.6g}" if isinstance(x, float) else str(x) for x in row) + "\n")
    print("| observable | demcal | LIGGGHTS | single-run scatter | offset (scatters) | ± (s.e.) |")
    print("|---|---|---|---|---|---|")
    for obs, md, ml, s, off, se, nl, nd in table:
        print(f"| `{obs}` | {md:.4g} | {ml:.4g} | {s:.3g} | {off:+.2f} | {se:.2f} |")
    cpu = sum(r["cpu_s"] for r in lig["heap"] + lig["funnel"])
    print(f"\nLIGGGHTS CPU: {cpu:.0f} s for {2 * n} runs; written {path}")


def read_vtk(path):
    """demcal's binary legacy VTK (big-endian): positions, radius_m, id per sphere."""
    data = open(path, "rb").read()
    out, pos = {}, 0

    def line():
        nonlocal pos
        end = data.index(b"\n", pos)
        text = data[pos:end].decode("latin-1")
        pos = end + 1
        return text
    while pos < len(data):
        words = line().split()
        if not words:
            continue
        if words[0] == "POINTS":
            n = int(words[1])
            out["xyz"] = struct.unpack(f">{3 * n}d", data[pos:pos + 24 * n])
            pos += 24 * n
        elif words[0] == "TIME":
            pos += 8
        elif words[0] in ("SCALARS", "VECTORS"):
            name, kind = words[1], words[2]
            if words[0] == "SCALARS":
                line()  # LOOKUP_TABLE
            count = len(out["xyz"]) // 3 * (3 if words[0] == "VECTORS" else 1)
            fmt, size = (">%dd" % count, 8) if kind == "double" else (">%di" % count, 4)
            out[name] = struct.unpack(fmt, data[pos:pos + size * count])
            pos += size * count
    return out


def check_port(out_dir, log):
    """The ported heap metric on demcal's own settled heaps against demcal's numbers."""
    result = json.load(open(os.path.join(out_dir, "result.json")))
    exp = mk.experiment("aor_bp_heap.json")
    m = mk.model_for(exp, "control", 0.0)
    aor = exp["aor"]
    fixed = int(aor["width_m"] // m.base_d) * int(aor["depth_m"] // m.base_d)
    worst = 0.0
    for run in result["runs"]:
        v = read_vtk(os.path.join(out_dir, f"heap_r{run['replicate']}.vtk"))
        xyz = v["xyz"]
        spheres = [(xyz[3 * i], xyz[3 * i + 2], v["radius_m"][i]) for i in range(len(v["id"])) if v["id"][i] >= fixed]
        got = measure.slot_heap(spheres, 1.125 * m.base_d)
        for k in mk.HEAP_OBS:
            diff = abs(got[k] - run[k])
            worst = max(worst, diff / (1.0 if k == "angle_deg" else 1e-3))
            print(f"r{run['replicate']} {k}: demcal {run[k]:.6g}  port {got[k]:.6g}")
    print(f"largest difference: {worst:.2e} (deg for angles, mm for lengths)")


def cli():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    what = ap.add_mutually_exclusive_group(required=True)
    what.add_argument("--agreement", metavar="BUILD_DIR")
    what.add_argument("--check-port", metavar="DEMCAL_AOR_OUT_DIR")
    ap.add_argument("--replicates", type=int, default=mk.REPLICATES)
    ap.add_argument("--agreement-rolling", choices=["off", "cdt"], default="off",
                    help="off: no rolling resistance in either engine; cdt: LIGGGHTS cdt against "
                         "demcal cdt_relative at the base coefficients")
    log = lambda s: print(time.strftime("%H:%M:%S ") + s, file=sys.stderr, flush=True)  # noqa: E731
    return main(ap.parse_args(), log)


if __name__ == "__main__":
    cli()
