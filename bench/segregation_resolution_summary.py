#!/usr/bin/env python3
"""Tables and plot of the fidelity-vs-resolution sweep (bench/segregation_resolution.sh).

Reads OUT/s<s>/<case>/r<r>/result.json (one replicate each) and writes
  OUT/segregation_resolution_runs.csv        one row per run: wall time, grains, EP indices + floor
  OUT/segregation_resolution.csv             per (s, case): mean and sample std over replicates
  OUT/segregation_resolution_separation.csv  per (s, region): adhesion - uncoated S_n of EP, its
                                             standard error, z, and replicates needed for z >= 2
  OUT/segregation_resolution.svg             S_n of EP (3D, front, back) against s, both cases,
                                             mean +- std, with the random-mixture 95 % band
With --with DIR (repeatable), the runs of earlier sweeps are added from DIR's
segregation_resolution_runs.csv (e.g. the committed bench/results/segregation_resolution_s*/), so
one table and one plot cover every fidelity measured; a run present in OUT_DIR (same s, case and
replicate) takes precedence over a copy from DIR.
Standard library only.
Usage: bench/segregation_resolution_summary.py OUT_DIR [--with RESULTS_DIR ...]
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys

REGIONS = ["3d", "2d_front", "2d_back"]
CASES = ["uncoated", "adhesion"]
SPECIES = "EP"


def value(stat):
    return None if stat is None else stat.get("mean")


def load_runs(out):
    rows = []
    for path in sorted(glob.glob(os.path.join(out, "s*", "*", "r*", "result.json"))):
        m = re.search(r"s([0-9.]+)/(\w+)/r(\d+)/result.json$", path)
        if not m or m.group(2) not in CASES:
            continue
        with open(path) as f:
            result = json.load(f)
        run = result["runs"][0]
        species = [s["name"] if "name" in s else s["species"] for s in result["species"]]
        ep = result["species"][species.index(SPECIES)]
        grains = run.get("heap_grains_per_species", [])
        row = {"size_scale": float(m.group(1)), "case": m.group(2),
               "replicate": int(m.group(3)), "seed": run["seed"], "status": run["status"],
               "wall_time_s": run["wall_time_s"], "heap_grains": run["particles"],
               "ep_grains": grains[species.index(SPECIES)] if len(grains) > 2 else None}
        for region in REGIONS:
            row["cov_" + region] = value(ep.get("cov_" + region))
            row["cov_r_" + region] = value(ep.get("cov_r_" + region))
            row["s_n_" + region] = value(ep.get("s_n_" + region))
            floor = ep.get("s_n_" + region + "_floor") or {}
            for k in ("mean", "low", "high"):
                row["s_n_%s_floor_%s" % (region, k)] = floor.get(k)
        rows.append(row)
    return rows


def load_runs_csv(results_dir):
    """Runs of an earlier sweep, as written to its segregation_resolution_runs.csv."""
    text_keys = {"case", "status", "seed"}
    rows = []
    with open(os.path.join(results_dir, "segregation_resolution_runs.csv")) as f:
        for raw in csv.DictReader(f):
            row = {}
            for k, v in raw.items():
                if k in text_keys:
                    row[k] = v
                elif k == "replicate":
                    row[k] = int(v)
                else:
                    row[k] = float(v) if v != "" else None
            rows.append(row)
    return rows


def merge_runs(own, earlier):
    """own first; an earlier run of the same (s, case, replicate) is dropped."""
    key = lambda r: (r["size_scale"], r["case"], r["replicate"])
    seen = {key(r) for r in own}
    merged = list(own)
    for r in earlier:
        if key(r) not in seen:
            seen.add(key(r))
            merged.append(r)
    return merged


def stats(values):
    v = [x for x in values if x is not None]
    if not v:
        return None, None, 0
    mean = sum(v) / len(v)
    sd = math.sqrt(sum((x - mean) ** 2 for x in v) / (len(v) - 1)) if len(v) > 1 else None
    return mean, sd, len(v)


def fmt(x):
    if x is None:
        return ""
    return str(x) if isinstance(x, int) else ("%.6g" % x)


def write_csv(path, header, rows):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for r in rows:
            w.writerow([fmt(r.get(h)) if not isinstance(r.get(h), str) else r[h] for h in header])
    os.replace(tmp, path)


def summarise(runs):
    groups = {}
    for r in runs:
        if r["status"] == "ok":
            groups.setdefault((r["size_scale"], r["case"]), []).append(r)
    table = []
    for (s, case), rs in sorted(groups.items(), key=lambda kv: (-kv[0][0], kv[0][1])):
        row = {"size_scale": s, "case": case, "runs_ok": len(rs)}
        for key in ["wall_time_s", "heap_grains", "ep_grains"]:
            row[key + "_mean"], row[key + "_std"], _ = stats([r[key] for r in rs])
        for region in REGIONS:
            for idx in ("cov_", "cov_r_", "s_n_"):
                k = idx + region
                row[k + "_mean"], row[k + "_std"], row[k + "_n"] = stats([r[k] for r in rs])
            for edge in ("mean", "low", "high"):
                k = "s_n_%s_floor_%s" % (region, edge)
                row[k], _, _ = stats([r[k] for r in rs])
        table.append(row)
    return table


def separation(table):
    by = {(r["size_scale"], r["case"]): r for r in table}
    rows = []
    for s in sorted({k[0] for k in by}, reverse=True):
        u, a = by.get((s, "uncoated")), by.get((s, "adhesion"))
        if not u or not a:
            continue
        for region in REGIONS:
            k = "s_n_" + region
            mu, ma = u[k + "_mean"], a[k + "_mean"]
            su, sa = u[k + "_std"], a[k + "_std"]
            nu, na = u[k + "_n"], a[k + "_n"]
            row = {"size_scale": s, "region": region, "uncoated_n": nu, "adhesion_n": na,
                   "uncoated_s_n": mu, "adhesion_s_n": ma,
                   "floor_high_uncoated": u["s_n_%s_floor_high" % region],
                   "floor_high_adhesion": a["s_n_%s_floor_high" % region]}
            if None not in (mu, ma, su, sa):
                delta = ma - mu
                se = math.sqrt(sa ** 2 / na + su ** 2 / nu)
                row["delta_s_n"] = delta
                row["delta_standard_error"] = se
                row["z"] = delta / se if se > 0 else None
                var = sa ** 2 + su ** 2
                row["replicates_for_z2"] = (math.ceil(4 * var / delta ** 2)
                                            if delta != 0 else None)
            rows.append(row)
    return rows


def svg_plot(table, path):
    w, h, panel_w = 960, 360, 300
    colours = {"uncoated": "#1f5fd6", "adhesion": "#d62728"}
    scales = sorted({r["size_scale"] for r in table})
    if not scales:
        return
    x_lo, x_hi = 1.0, max(scales) + 0.5
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
             'font-family="sans-serif">' % (w, h),
             '<rect width="100%" height="100%" fill="white"/>']
    titles = {"3d": "S_n EP, whole heap (3D, mass)", "2d_front": "S_n EP, front face (number)",
              "2d_back": "S_n EP, back face (number)"}
    for p, region in enumerate(REGIONS):
        left, top, pw, ph = 50 + p * (panel_w + 20), 40, panel_w - 40, h - 110
        vals = [0.0]
        for r in table:
            for k in ("_mean",):
                m, sd = r["s_n_" + region + k], r["s_n_" + region + "_std"] or 0
                if m is not None:
                    vals.append(m + sd)
            if r["s_n_%s_floor_high" % region] is not None:
                vals.append(r["s_n_%s_floor_high" % region])
        y_hi = max(vals) * 1.1 or 1.0
        px = lambda x: left + (x - x_lo) / (x_hi - x_lo) * pw
        py = lambda y: top + ph - y / y_hi * ph
        parts.append('<text x="%d" y="%d" font-size="13">%s</text>' % (left, top - 14,
                                                                       titles[region]))
        parts.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' %
                     (left, top + ph, left + pw, top + ph))
        parts.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' %
                     (left, top, left, top + ph))
        for t in range(5):
            y = y_hi * t / 4
            parts.append('<text x="%d" y="%.1f" font-size="10" text-anchor="end">%.2f</text>' %
                         (left - 4, py(y) + 3, y))
        for s in scales:
            parts.append('<text x="%.1f" y="%d" font-size="10" text-anchor="middle">%g</text>' %
                         (px(s), top + ph + 14, s))
        parts.append('<text x="%.1f" y="%d" font-size="11" text-anchor="middle">coarse-graining '
                     's (size_scale)</text>' % (left + pw / 2, top + ph + 30))
        parts.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#999" '
                     'stroke-dasharray="3,3"/>' % (left, py(1), left + pw, py(1)))
        for case, dx in (("uncoated", -0.06), ("adhesion", 0.06)):
            rows = sorted([r for r in table if r["case"] == case], key=lambda r: r["size_scale"])
            for r in rows:
                lo, hi = r["s_n_%s_floor_low" % region], r["s_n_%s_floor_high" % region]
                if lo is not None and hi is not None:
                    parts.append('<rect x="%.1f" y="%.1f" width="10" height="%.1f" fill="%s" '
                                 'fill-opacity="0.15"/>' % (px(r["size_scale"] + dx) - 5, py(hi),
                                                           py(lo) - py(hi), colours[case]))
                m, sd = r["s_n_" + region + "_mean"], r["s_n_" + region + "_std"]
                if m is None:
                    continue
                x = px(r["size_scale"] + dx)
                if sd:
                    parts.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s"/>' %
                                 (x, py(m - sd), x, py(m + sd), colours[case]))
                parts.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="%s"/>' %
                             (x, py(m), colours[case]))
    legend_y = h - 30
    for i, case in enumerate(CASES):
        label = {"uncoated": "uncoated EP", "adhesion": "excessive adhesion (0.25 J/m2 on EP)"}
        parts.append('<circle cx="%d" cy="%d" r="4" fill="%s"/>' % (60 + i * 260, legend_y,
                                                                   colours[case]))
        parts.append('<text x="%d" y="%d" font-size="11">%s</text>' %
                     (70 + i * 260, legend_y + 4, label[case]))
    parts.append('<text x="580" y="%d" font-size="11">bars: mean +- std over replicates; '
                 'boxes: 95%% random-mixture band</text>' % (legend_y + 4))
    parts.append("</svg>")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(parts) + "\n")
    os.replace(tmp, path)


def main():
    parser = argparse.ArgumentParser(description="Tables and plot of the fidelity sweep.")
    parser.add_argument("out", metavar="OUT_DIR")
    parser.add_argument("--with", dest="earlier", metavar="RESULTS_DIR", action="append",
                        default=[], help="add the runs of an earlier sweep (repeatable)")
    args = parser.parse_args()
    bad = [d for d in [args.out] + args.earlier if not os.path.isdir(d)]
    if bad:
        parser.error("not a directory: %s" % ", ".join(bad))
    out = args.out
    runs = load_runs(out)
    for d in args.earlier:
        runs = merge_runs(runs, load_runs_csv(d))
    if not runs:
        sys.stderr.write("no finished runs (s*/<case>/r*/result.json) in %s\n" % out)
        return 1
    run_header = list(runs[0].keys())
    write_csv(os.path.join(out, "segregation_resolution_runs.csv"), run_header, runs)
    table = summarise(runs)
    if table:
        write_csv(os.path.join(out, "segregation_resolution.csv"), list(table[0].keys()), table)
        svg_plot(table, os.path.join(out, "segregation_resolution.svg"))
    sep = separation(table)
    sep_header = ["size_scale", "region", "uncoated_n", "adhesion_n", "uncoated_s_n",
                  "adhesion_s_n", "delta_s_n", "delta_standard_error", "z", "replicates_for_z2",
                  "floor_high_uncoated", "floor_high_adhesion"]
    write_csv(os.path.join(out, "segregation_resolution_separation.csv"), sep_header, sep)
    for r in sep:
        sys.stderr.write("s=%g %-8s S_n uncoated %s (n=%s) adhesion %s (n=%s) z=%s need R=%s\n" % (
            r["size_scale"], r["region"], fmt(r["uncoated_s_n"]), r["uncoated_n"],
            fmt(r["adhesion_s_n"]), r["adhesion_n"], fmt(r.get("z")),
            r.get("replicates_for_z2", "")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
