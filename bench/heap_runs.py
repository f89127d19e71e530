"""Helpers shared by the heap benchmark scripts (mixture_angle_confinement.py,
clump_heap_size.py, clump_funnel.py): one timed quick experiment run and its result, the CPU
time of a run from its `/usr/bin/time -v` log, the mean with its standard error over replicate
heaps, and the runs.csv / arms.csv tables."""
import csv
import json
import math
import os
import re
import subprocess


def run_quick(demcal, kind, params, folder, replicates=1):
    """`demcal experiment KIND PARAMS --out FOLDER --quick --replicates N --threads 1` under
    `nice -n 5` and `/usr/bin/time -v` (FOLDER/time.txt), its output in FOLDER/log.txt."""
    cmd = ["nice", "-n", "5", "/usr/bin/time", "-v", "-o", os.path.join(folder, "time.txt"), demcal,
           "experiment", kind, params, "--out", folder, "--quick", "--replicates", str(replicates),
           "--threads", "1"]
    with open(os.path.join(folder, "log.txt"), "w") as log:
        subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT)


def read_result(folder):
    """FOLDER/result.json of a run_quick run and its CPU seconds per heap; (None, NaN) while the
    run has not finished."""
    try:
        res = json.load(open(os.path.join(folder, "result.json")))
    except (OSError, ValueError):
        return None, float("nan")
    return res, cpu_seconds(os.path.join(folder, "time.txt")) / max(1, len(res["runs"]))


def cpu_seconds(time_log):
    """User + system seconds from a `/usr/bin/time -v` log; NaN when the log is missing or cut."""
    try:
        text = open(time_log).read()
    except OSError:
        return float("nan")
    user = re.search(r"User time \(seconds\): ([0-9.]+)", text)
    system = re.search(r"System time \(seconds\): ([0-9.]+)", text)
    return float(user.group(1)) + float(system.group(1)) if user and system else float("nan")


def mean_sem(xs):
    """Mean and standard error of the finite numbers in xs (NaN where they do not exist)."""
    xs = [x for x in xs if isinstance(x, (int, float)) and math.isfinite(x)]
    if not xs:
        return float("nan"), float("nan")
    m = sum(xs) / len(xs)
    if len(xs) < 2:
        return m, float("nan")
    return m, math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1) / len(xs))


def write_tables(out, rows, arms, keys, keep=lambda row: True):
    """OUT/runs.csv (every row) and OUT/arms.csv (per arm, over the rows `keep` accepts: the
    count, and mean and standard error of each key); prints arms.csv."""
    with open(os.path.join(out, "runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out, "arms.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["arm", "heaps"] + [k + suffix for k in keys for suffix in ("", "_sem")])
        for arm in arms:
            rs = [r for r in rows if r["arm"] == arm and keep(r)]
            if rs:
                w.writerow([arm, len(rs)] + [f"{v:.4g}" for k in keys
                                             for v in mean_sem([r[k] for r in rs])])
    print(open(os.path.join(out, "arms.csv")).read())


def set_pair(exp, a, b, key, value):
    """Sets `key` of the (a, b) pair in an experiment file's interactions.pairs (either order),
    adding the pair when it is not listed."""
    for p in exp["interactions"]["pairs"]:
        if sorted(p["materials"]) == sorted([a, b]):
            p[key] = value
            return
    exp["interactions"]["pairs"].append({"materials": [a, b], key: value})
