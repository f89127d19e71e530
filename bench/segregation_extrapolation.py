#!/usr/bin/env python3
"""The segregation indices of the fidelity sweep carried to the paper's fidelity (size x1).

The heap cannot be afforded at the paper's grain size on this project's machines, so each index
is measured at coarser fidelities (bench/segregation_resolution.sh: size_scale s = 5, 3, 2, 1.5)
and extrapolated to s = 1 with its uncertainty. Extrapolating S_n or CoV directly would mix two
things the fidelity changes differently:
  * the sampling noise of finite grains per bin, which a random mixture of the same heap shows
    too (its CoV is the floor S_n,floor x CoV_r; S_n,floor is the random-relabelling floor the
    experiment reports, CoV_r the paper's random-mixture CoV, Eq. 6, which scales as s^(3/2):
    grains per bin ~ s^-3), known exactly at any s;
  * the segregation itself, the variance left when the sampling variance is taken out:
        v = CoV^2 - (S_n,floor x CoV_r)^2        (independent variances add)
    which would not depend on s if the coarse-grained physics had converged.
So v is what is extrapolated: a weighted least-squares line in s (model A, the central value)
and a line in s^2 (model B; coarse-graining errors of a contact model are commonly first or
second order in the grain size), the two models' difference taken as a systematic uncertainty.
Then at s = 1:  CoV = sqrt(v + (floor x CoV_r(1))^2),  S_n = CoV / CoV_r(1),  CoV_seg = sqrt(v),
with CoV_r(1) from a power-law fit of CoV_r over every run and the floor the mean over runs.
Uncertainties: per size the larger of the replicate standard error and the sampling standard
error (the floor's 95 % band / 3.92 x CoV_r, by the delta method for CoV^2); a size with one run
has only the sampling part (said in the table). The s = 1 values carry a seeded Monte Carlo
(10,000 draws of v, CoV_r(1) and the floor from their estimates): median and the 16-84 %
interval. The wall time at s = 1 is a power-law fit of run wall time against heap grains.

Input: a segregation_resolution_runs.csv (bench/segregation_resolution_summary.py). Output: the
table on stdout and, with --out, a CSV (columns below). --self-test checks the method on runs made
from a known law. Standard library only.
Usage: bench/segregation_extrapolation.py [RUNS_CSV] [--region 3d] [--out CSV] | --self-test
"""
import argparse
import csv
import math
import random
import sys

DEFAULT_RUNS = "bench/results/segregation_resolution_all/segregation_resolution_runs.csv"
TARGET_S = 1.0
Z95 = 1.959964  # the floor's band is its central 95 % interval
DRAWS = 10000


def num(x):
    return float(x) if x not in (None, "") else None


def read_runs(path, region):
    runs = []
    with open(path) as f:
        for r in csv.DictReader(f):
            if r.get("status", "ok") != "ok":
                continue
            cov, cov_r = num(r["cov_" + region]), num(r["cov_r_" + region])
            floor = [num(r["s_n_%s_floor_%s" % (region, k)]) for k in ("mean", "low", "high")]
            if cov is None or cov_r is None or None in floor:
                continue
            runs.append({"s": float(r["size_scale"]), "case": r["case"], "cov": cov,
                         "cov_r": cov_r, "floor": floor[0],
                         "floor_sd": (floor[2] - floor[1]) / (2 * Z95),
                         "wall": num(r.get("wall_time_s")), "grains": num(r.get("heap_grains"))})
    return runs


def segregation_variance(run):
    """v and its sampling standard error for one run (delta method on CoV^2)."""
    floor_cov = run["floor"] * run["cov_r"]
    v = run["cov"] ** 2 - floor_cov ** 2
    cov_sd = run["floor_sd"] * run["cov_r"]
    return v, 2 * run["cov"] * cov_sd


def per_size(runs):
    """{s: (mean v, standard error, runs, 'replicates' or 'sampling only')}."""
    out = {}
    for s in sorted({r["s"] for r in runs}, reverse=True):
        vs = [segregation_variance(r) for r in runs if r["s"] == s]
        n = len(vs)
        mean = sum(v for v, _ in vs) / n
        sampling_se = math.sqrt(sum(se ** 2 for _, se in vs)) / n
        if n > 1:
            sd = math.sqrt(sum((v - mean) ** 2 for v, _ in vs) / (n - 1))
            out[s] = (mean, max(sd / math.sqrt(n), sampling_se), n, "replicates")
        else:
            out[s] = (mean, sampling_se, n, "sampling only")
    return out


def weighted_line(xs, ys, ses):
    """y = a + b x by weighted least squares: (a, b, cov matrix, chi2, dof)."""
    w = [1 / se ** 2 for se in ses]
    sw = sum(w)
    sx = sum(wi * x for wi, x in zip(w, xs))
    sy = sum(wi * y for wi, y in zip(w, ys))
    sxx = sum(wi * x * x for wi, x in zip(w, xs))
    sxy = sum(wi * x * y for wi, x, y in zip(w, xs, ys))
    det = sw * sxx - sx * sx
    a = (sxx * sy - sx * sxy) / det
    b = (sw * sxy - sx * sy) / det
    cov = [[sxx / det, -sx / det], [-sx / det, sw / det]]
    chi2 = sum(wi * (y - a - b * x) ** 2 for wi, x, y in zip(w, xs, ys))
    return a, b, cov, chi2, len(xs) - 2


def at(fit, x):
    """The fitted line's value at x and its standard error; the error is inflated by
    sqrt(chi2/dof) when the line misses its points by more than their errors."""
    a, b, cov, chi2, dof = fit
    var = cov[0][0] + 2 * x * cov[0][1] + x * x * cov[1][1]
    scale = max(1.0, chi2 / dof) if dof > 0 else 1.0
    return a + b * x, math.sqrt(var * scale)


def power_law(xs, ys):
    """log y = c + k log x by least squares: (c, k, residual sd of log y)."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((x - mx) ** 2 for x in lx)
    k = sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / sxx
    c = my - k * mx
    resid = math.sqrt(sum((y - c - k * x) ** 2 for x, y in zip(lx, ly)) / max(1, n - 2))
    return c, k, resid


def quantiles(values):
    v = sorted(values)
    pick = lambda q: v[min(len(v) - 1, int(q * len(v)))]
    return pick(0.16), pick(0.5), pick(0.84)


def extrapolate(runs, seed=2018):
    """Per case: the per-size table and the s = 1 estimates (dict)."""
    results = {}
    for case in sorted({r["case"] for r in runs}):
        mine = [r for r in runs if r["case"] == case]
        sizes = per_size(mine)
        if len(sizes) < 3:
            results[case] = {"sizes": sizes, "error": "fewer than 3 fidelities"}
            continue
        xs = sorted(sizes)
        ys, ses = [sizes[s][0] for s in xs], [sizes[s][1] for s in xs]
        line = weighted_line(xs, ys, ses)
        square = weighted_line([x * x for x in xs], ys, ses)
        v_a, se_a = at(line, TARGET_S)
        v_b, _ = at(square, TARGET_S * TARGET_S)
        systematic = abs(v_a - v_b)
        c, k, resid = power_law([r["s"] for r in mine], [r["cov_r"] for r in mine])
        floors = [r["floor"] for r in mine]
        floor_mean = sum(floors) / len(floors)
        floor_sd = math.sqrt(sum((f - floor_mean) ** 2 for f in floors) / max(1, len(floors) - 1))
        rng = random.Random(seed)
        cov_seg, cov, s_n = [], [], []
        v_sd = math.hypot(se_a, systematic)
        cov_r_sd = resid / math.sqrt(len(mine))
        for _ in range(DRAWS):
            v = rng.gauss(v_a, v_sd)
            cov_r1 = math.exp(rng.gauss(c + k * math.log(TARGET_S), cov_r_sd))
            floor = rng.gauss(floor_mean, floor_sd)
            noise = (floor * cov_r1) ** 2
            total = max(v + noise, 0.0)
            cov_seg.append(math.copysign(math.sqrt(abs(v)), v))
            cov.append(math.sqrt(total))
            s_n.append(math.sqrt(total) / cov_r1)
        wall = [(r["grains"], r["wall"]) for r in mine if r["wall"] and r["grains"]]
        wall_fit = power_law([g for g, _ in wall], [t for _, t in wall]) if len(wall) > 2 else None
        grains_fit = power_law([r["s"] for r in mine if r["grains"]],
                               [r["grains"] for r in mine if r["grains"]])
        grains1 = math.exp(grains_fit[0] + grains_fit[1] * math.log(TARGET_S))
        results[case] = {
            "sizes": sizes, "v_line": (v_a, se_a), "v_square": v_b, "systematic": systematic,
            "line_chi2_dof": (line[3], line[4]),
            "cov_r_exponent": k, "cov_r_at_1": math.exp(c), "floor": (floor_mean, floor_sd),
            "cov_seg": quantiles(cov_seg), "cov": quantiles(cov), "s_n": quantiles(s_n),
            "grains_at_1": grains1,
            "wall_at_1_s": (math.exp(wall_fit[0] + wall_fit[1] * math.log(grains1))
                            if wall_fit else None),
            "wall_exponent": wall_fit[1] if wall_fit else None}
    return results


def rows(results):
    out = []
    for case, r in results.items():
        if "error" in r:
            out.append([case, "error", "", "", "", r["error"]])
            continue
        note = "model A (v linear in s); model B (v linear in s^2) %.4g" % r["v_square"]
        for name, q in (("cov_seg", r["cov_seg"]), ("cov", r["cov"]), ("s_n", r["s_n"])):
            out.append([case, name, "%.4g" % q[1], "%.4g" % q[0], "%.4g" % q[2], note])
        out.append([case, "cov_r", "%.4g" % r["cov_r_at_1"], "", "",
                    "power-law exponent in s %.3f (Eq. 6 expects 1.5)" % r["cov_r_exponent"]])
        out.append([case, "heap_grains", "%.0f" % r["grains_at_1"], "", "", "power law in s"])
        if r["wall_at_1_s"]:
            out.append([case, "wall_time_s", "%.0f" % r["wall_at_1_s"], "", "",
                        "power law in heap grains, exponent %.2f; the runs' machine and load"
                        % r["wall_exponent"]])
    return out


def print_table(results, region):
    print("segregation indices of EP (%s) at size x%g, extrapolated" % (region, TARGET_S))
    for case, r in results.items():
        print("\n%s" % case)
        for s, (v, se, n, kind) in sorted(r["sizes"].items(), reverse=True):
            print("  s %-4g v = CoV^2 - floor^2 = %.4f +- %.4f  (%d run(s), %s)" % (s, v, se, n, kind))
        if "error" in r:
            print("  " + r["error"])
            continue
        print("  v(1): line %.4f +- %.4f (chi2 %.2f on %d dof), square %.4f, systematic %.4f"
              % (r["v_line"][0], r["v_line"][1], r["line_chi2_dof"][0], r["line_chi2_dof"][1],
                 r["v_square"], r["systematic"]))
        for name in ("cov_seg", "cov", "s_n"):
            lo, mid, hi = r[name]
            print("  %-8s %.3f  [%.3f, %.3f] (16-84 %%)" % (name, mid, lo, hi))
        print("  CoV_r(1) %.4f (exponent %.3f), floor %.3f +- %.3f, heap grains %.0f"
              % (r["cov_r_at_1"], r["cov_r_exponent"], r["floor"][0], r["floor"][1],
                 r["grains_at_1"]))
        if r["wall_at_1_s"]:
            print("  wall time of one heap at x1: %.0f s (exponent %.2f in grains)"
                  % (r["wall_at_1_s"], r["wall_exponent"]))


def self_test():
    """Runs made from a known law: v = 0.1 + 0.02 s, CoV_r = 0.07 s^1.5, floor 1.7 (band
    +-0.3); noise-free runs must give the law's s = 1 values, and noisy ones must bracket them."""
    def run(s, case, v, jitter=0.0):
        cov_r = 0.07 * s ** 1.5
        cov = math.sqrt(v + jitter + (1.7 * cov_r) ** 2)
        return {"s": s, "case": case, "cov": cov, "cov_r": cov_r, "floor": 1.7,
                "floor_sd": 0.6 / (2 * Z95), "wall": 10 * s ** -4, "grains": 5000 * s ** -3}
    law = lambda s: 0.1 + 0.02 * s
    exact = [run(s, "law", law(s)) for s in (5, 3, 2, 1.5) for _ in range(2)]
    r = extrapolate(exact)["law"]
    v1 = law(1.0)
    cov1 = math.sqrt(v1 + (1.7 * 0.07) ** 2)
    failures = []
    check = lambda what, got, want, tol: failures.append(
        "%s: %.6g, expected %.6g" % (what, got, want)) if abs(got - want) > tol else None
    check("v(1) line", r["v_line"][0], v1, 1e-9)
    check("CoV_r exponent", r["cov_r_exponent"], 1.5, 1e-9)
    check("CoV(1)", r["cov"][1], cov1, 0.01 * cov1)
    check("S_n(1)", r["s_n"][1], cov1 / 0.07, 0.01 * cov1 / 0.07)
    check("wall time", r["wall_at_1_s"], 10.0, 1e-6)
    rng = random.Random(7)
    noisy = [run(s, "law", law(s), rng.gauss(0, 0.004)) for s in (5, 3, 2, 1.5) for _ in range(3)]
    q = extrapolate(noisy)["law"]["s_n"]
    if not q[0] <= cov1 / 0.07 <= q[2] and abs(q[1] - cov1 / 0.07) > 0.1 * cov1 / 0.07:
        failures.append("noisy S_n(1) interval [%.3f, %.3f] misses %.3f" % (q[0], q[2], cov1 / 0.07))
    few = extrapolate([run(s, "few", law(s)) for s in (3, 2)])["few"]
    if "error" not in few:
        failures.append("two fidelities were extrapolated")
    for f in failures:
        print("self-test FAILED: " + f)
    print("self-test: %s" % ("pass" if not failures else "fail"))
    return 1 if failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs", nargs="?", default=DEFAULT_RUNS)
    p.add_argument("--region", default="3d", choices=["3d", "2d_front", "2d_back"])
    p.add_argument("--out", help="write the s = 1 table as CSV")
    p.add_argument("--self-test", action="store_true")
    a = p.parse_args()
    if a.self_test:
        return self_test()
    try:
        runs = read_runs(a.runs, a.region)
    except (OSError, KeyError, ValueError) as e:
        print("%s: cannot read the runs table (%s)" % (a.runs, e), file=sys.stderr)
        return 2
    if not runs:
        print("%s: no finished run with %s indices" % (a.runs, a.region), file=sys.stderr)
        return 2
    results = extrapolate(runs)
    print_table(results, a.region)
    if a.out:
        with open(a.out, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["case", "quantity", "value_at_size_x1", "low_16pct", "high_84pct", "note"])
            w.writerows(rows(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
