#!/usr/bin/env python3
"""Diagnosis studies of the LIGGGHTS-made cases whose base model uses LIGGGHTS' own rolling law.

  python3 scripts/liggghts_matching_studies.py [--cases control,rolling_low,...]

The datasets' base (datasets/liggghts_crossengine/README.md) rolls by LIGGGHTS `rolling_friction
cdt` at 0.20 between grains and 0.055 against the walls. demcal's `cdt` is EDEM's law, not that
one (docs/physics.md section 2.1), so a base model with it carries a model-form offset that hides
rolling and wall effects. A user who knows the data came from LIGGGHTS' cdt picks the same law:
demcal `cdt_relative` at the same coefficients (the same torque, no conversion). This writes
 - examples/diagnose/<experiment>_cdt_relative.json: the four experiment files of the studies
   (rig 1, rig 2, the funnel, rig 3: the narrow funnel) with that law and those coefficients, all
   else unchanged;
 - examples/diagnose/crossengine_<case>_cdt_relative.json: each case's study
   (crossengine_<case>.json, written by make_liggghts_datasets.py) on those experiment files.
The study still fits only the BP-BP sliding friction; nothing else is read from the data.
"""
import json, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_liggghts_datasets as mk  # noqa: E402

EXAMPLES = os.path.join(mk.ROOT, "examples", "diagnose")
EXPERIMENTS = ("aor_bp_heap.json", "aor_bp_heap_narrow.json", "discharge_bp_small.json", "discharge_bp_narrow.json")
SUFFIX = "_cdt_relative"


def matching_name(name):
    return name[:-len(".json")] + SUFFIX + ".json"


def write(path, doc):
    json.dump(doc, open(path, "w"), indent=2)
    open(path, "a").write("\n")


def write_experiment(name):
    exp = mk.experiment(name)
    exp["description"] = (
        f"{name} with LIGGGHTS' constant-torque rolling law (demcal cdt_relative, docs/physics.md "
        f"section 2.1) at the LIGGGHTS-made datasets' base coefficients, {mk.BASE['mur_pp']} between "
        f"grains and {mk.BASE['mur_pw']} against the walls (datasets/liggghts_crossengine/README.md); "
        "written by scripts/liggghts_matching_studies.py. Everything else as " + name + ": " +
        exp["description"])
    exp["interactions"]["default"]["rolling_friction"] = mk.BASE["mur_pp"]
    for pair in exp["interactions"]["pairs"]:
        pair["rolling_friction"] = mk.BASE["mur_pw"]
    exp["contact_model"] = {**exp.get("contact_model", {}), "rolling": "cdt_relative"}
    write(os.path.join(EXAMPLES, matching_name(name)), exp)


def write_study(case, folder=EXAMPLES, where=None):
    """folder/crossengine_<case>_cdt_relative.json from folder/crossengine_<case>.json (an experiment
    file given by an absolute path keeps its folder)."""
    study = json.load(open(os.path.join(folder, f"crossengine_{case}.json")))
    for target in study["targets"]:
        target["experiment_file"] = matching_name(target["experiment_file"])
    where = where or f"case {case} of datasets/liggghts_crossengine/"
    study["description"] = (
        f"Diagnosis on OTHER-ENGINE data: LIGGGHTS-made (not measured, not made by demcal), {where}, "
        "with the base on the data's own rolling law: demcal "
        f"cdt_relative (LIGGGHTS' cdt) at {mk.BASE['mur_pp']} between grains and {mk.BASE['mur_pw']} "
        "against the walls, BP-BP sliding friction fitted; rig 1 (16 mm slot heap) at 0, 1.5 and 3 wt% "
        "PEG, rig 2 (12.5 mm slot heap) at 0 and 3 wt%, the funnel and rig 3 (the narrow funnel) at 0 wt%. "
        "Written by "
        "scripts/liggghts_matching_studies.py. Run with --quick, the fidelity the data were made at.")
    write(os.path.join(folder, f"crossengine_{case}{SUFFIX}.json"), study)


def main():
    cases = mk.cases_from_arguments(__doc__.split("\n")[0])
    for name in EXPERIMENTS:
        write_experiment(name)
    for case in cases:
        write_study(case)


if __name__ == "__main__":
    main()
