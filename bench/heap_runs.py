"""Helpers shared by the heap benchmark scripts (mixture_angle_confinement.py,
clump_heap_size.py): the CPU time of a run from its `/usr/bin/time -v` log, and the mean with its
standard error over replicate heaps."""
import math
import re


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
