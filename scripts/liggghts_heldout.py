"""Held-out variants of the LIGGGHTS-made cases: the flags of scripts/make_liggghts_datasets.py that
make a case at another strength (--change), under another name (--name), on other seeds
(--seed-base, --noise-seed) into another folder (--out), and their checks.

A held-out dataset must never overwrite the bundled ones: any of these flags away from its default
needs an --out other than datasets/liggghts_crossengine.
"""
import json
import math
import os
import re


def _number(lo, hi, lo_open=True):
    def check(v):
        ok = isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and \
            (v > lo if lo_open else v >= lo) and v <= hi
        return ok, f"a number in {'(' if lo_open else '['}{lo:g}, {hi:g}]"
    return check


def _diameters(v):
    ok = (isinstance(v, list) and len(v) == 2 and all(_number(0, 2e-3)(d)[0] for d in v) and v[0] < v[1])
    return ok, "[min, max] in metres, 0 < min < max <= 0.002"


# Every key a case's hidden change can carry (make_liggghts_datasets.CASES), and what it accepts.
CHANGE_KEYS = {
    "ced_J_m3_per_wt_pct": _number(0, 1e5),
    "rolling": lambda v: (v in ("cdt", "epsd2"), "\"cdt\" or \"epsd2\""),
    "mur_pp": _number(0, 1),
    "mu_pw": _number(0, 2),
    "clump": _number(1, 5),
    "diameter_range_m": _diameters,
}
# Changes whose sign follows from the value against the base (same law): rolling friction by cdt
# between grains, sliding friction against the walls. Every other change keeps its case's sign.
SIGNED_KEYS = ("mur_pp", "mu_pw")


def add_arguments(ap, out, seed_base, noise_seed):
    ap.add_argument("--out", default=out, help="folder of the case folders; another folder also gets "
                    "studies/crossengine_<name>.json and its _cdt_relative variant (default: %(default)s)")
    ap.add_argument("--seed-base", type=int, default=seed_base, help="first seed (default: %(default)s)")
    ap.add_argument("--noise-seed", type=int, default=noise_seed,
                    help="noise draw: random.Random(NOISE_SEED + case index) (default: %(default)s)")
    ap.add_argument("--change", action="append", default=[], metavar="KEY=JSON",
                    help="override a key of the case's hidden change, e.g. 'mur_pp=0.1' (repeatable; "
                    f"keys: {', '.join(CHANGE_KEYS)}; only keys the case already changes)")
    ap.add_argument("--name", help="name of the output case folder (default: the case's name; one case only)")


def _parse_change(text, case, change):
    key, sep, value = text.partition("=")
    if not sep:
        raise SystemExit(f"--change: '{text}' is not KEY=JSON (keys: {', '.join(CHANGE_KEYS)})")
    if key not in change:
        allowed = ", ".join(change) or "none: the case has no hidden change"
        raise SystemExit(f"--change: case '{case}' does not change '{key}' (keys it changes: {allowed})")
    try:
        v = json.loads(value)
    except json.JSONDecodeError as e:
        raise SystemExit(f"--change {key}: '{value}' is not JSON ({e})")
    ok, allowed = CHANGE_KEYS[key](v)
    if not ok:
        raise SystemExit(f"--change {key}: {value} is not allowed (allowed: {allowed})")
    return key, v


def _sign(case, change, default_sign, base):
    """The hidden change's sign: from its value against the base where the law is the same."""
    key = next((k for k in SIGNED_KEYS if k in change), None)
    if key is None or (key == "mur_pp" and change.get("rolling", "cdt") != "cdt"):
        return default_sign
    if change[key] == base[key]:
        raise SystemExit(f"--change {key}: {change[key]} is the base value: case '{case}' would hide nothing")
    return "+" if change[key] > base[key] else "-"


def specs(a, cases, base, bundled_out, seed_base, noise_seed):
    """One spec per case of --cases: case, name, change, sign, seeds, out, held_out (written outside the
    bundled folder) and variant (any flag but --out away from its default)."""
    names = a.cases.split(",")
    for case in names:
        if case not in cases:
            raise SystemExit(f"--cases: unknown case '{case}' (known: {', '.join(cases)})")
    out = os.path.abspath(a.out)
    held_out = out != os.path.abspath(bundled_out)
    varied = [flag for flag, v, d in (("--seed-base", a.seed_base, seed_base), ("--noise-seed", a.noise_seed, noise_seed),
                                      ("--change", a.change, []), ("--name", a.name, None)) if v != d]
    if varied and not held_out:
        raise SystemExit(f"{', '.join(varied)}: held-out data need --out DIR other than {bundled_out} "
                         "(the bundled datasets are made with the defaults only)")
    if (a.change or a.name) and len(names) != 1:
        raise SystemExit("--change and --name: give exactly one case in --cases")
    if a.name is not None and not re.fullmatch(r"[A-Za-z0-9_]+", a.name):
        raise SystemExit(f"--name: '{a.name}' must be letters, digits and underscores")
    out_specs = []
    for case in names:
        effect, change, sign = cases[case]
        change = dict(change)
        for text in a.change:
            key, v = _parse_change(text, case, change)
            change[key] = v
        if a.change:
            sign = _sign(case, change, sign, base)
        out_specs.append({"case": case, "name": a.name or case, "change": change, "sign": sign,
                          "seed_base": a.seed_base, "noise_seed": a.noise_seed, "out": out,
                          "held_out": held_out, "variant": bool(varied)})
    return out_specs


def self_test():
    """The flags' checks on made-up cases (no LIGGGHTS run)."""
    import argparse
    cases = {"control": (None, {}, None), "rolling_low": ("rolling_resistance", {"mur_pp": 0.05}, "-"),
             "wall": ("wall_friction", {"mu_pw": 0.9}, "+")}
    base = {"mur_pp": 0.2, "mu_pw": 0.42}

    def run(argv, bundled="/repo/bundled"):
        ap = argparse.ArgumentParser()
        ap.add_argument("--cases", default="control")
        add_arguments(ap, bundled, 100, 200)
        return specs(ap.parse_args(argv), cases, base, bundled, 100, 200)

    def fails(argv, needle):
        try:
            run(argv)
        except SystemExit as e:
            assert needle in str(e), (argv, str(e))
            return
        raise AssertionError(f"{argv} was accepted")

    default = run([])[0]
    assert not default["held_out"] and not default["variant"] and default["seed_base"] == 100
    s = run(["--out", "/tmp/x", "--cases", "rolling_low", "--change", "mur_pp=0.1", "--name", "rl"])[0]
    assert (s["name"], s["change"], s["sign"], s["held_out"]) == ("rl", {"mur_pp": 0.1}, "-", True)
    assert run(["--out", "/tmp/x", "--cases", "rolling_low", "--change", "mur_pp=0.3"])[0]["sign"] == "+"
    assert run(["--out", "/tmp/x", "--cases", "wall", "--change", "mu_pw=0.3"])[0]["sign"] == "-"
    assert not run(["--out", "/tmp/x"])[0]["variant"]  # only --out: the bundled recipe text
    fails(["--seed-base", "5"], "--seed-base: held-out data need --out")
    fails(["--out", "/tmp/x", "--change", "mur_pp=0.1"], "case 'control' does not change 'mur_pp'")
    fails(["--out", "/tmp/x", "--cases", "rolling_low", "--change", "mur_pp=1.5"], "allowed: a number in (0, 1]")
    fails(["--out", "/tmp/x", "--cases", "rolling_low", "--change", "mur_pp=0.2"], "is the base value")
    fails(["--out", "/tmp/x", "--cases", "rolling_low", "--change", "mur_pp"], "is not KEY=JSON")
    fails(["--out", "/tmp/x", "--cases", "rolling_low,wall", "--name", "a"], "exactly one case")
    fails(["--out", "/tmp/x", "--name", "../a"], "letters, digits and underscores")
    fails(["--out", "/tmp/x", "--cases", "nope"], "unknown case 'nope'")
    print("liggghts_heldout self-test: pass")


if __name__ == "__main__":
    import sys
    if sys.argv[1:] != ["--self-test"]:
        raise SystemExit("usage: python3 scripts/liggghts_heldout.py --self-test (the flags: make_liggghts_datasets.py)")
    self_test()
