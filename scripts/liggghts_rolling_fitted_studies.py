#!/usr/bin/env python3
"""Diagnosis studies of the LIGGGHTS-made cases with the rolling friction fitted in the base.

  python3 scripts/liggghts_rolling_fitted_studies.py [--cases control,rolling_low,...]

The datasets roll by LIGGGHTS' `rolling_friction cdt`; the studies' base rolls by demcal's `cdt`
(EDEM's law, docs/physics.md section 2.1) at an assumed 0.10, which carries an offset in the
rolling law: LIGGGHTS' torque at the same coefficient is about half demcal's. A user who does not
know the other engine's law, or whose data come from a lab, fits the rolling friction with the
sliding friction, so that the offset becomes a base value and not a missing effect
(docs/diagnose/base_fit.md, "Rolling friction in the base"). This writes
examples/diagnose/crossengine_<case>_fit_rolling.json from crossengine_<case>.json (written by
make_liggghts_datasets.py): the same targets and experiment files, and one more fitted parameter,
the BP-BP rolling friction in [0.01, 0.5] from the assumed 0.10 (a tenth to five times it: the
LIGGGHTS base's 0.20 on its own law is about 0.05 on demcal's). The `rolling_resistance` effect is
then a copy of a fitted parameter, guarded as a control.
"""
import json, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_liggghts_datasets as mk  # noqa: E402

EXAMPLES = os.path.join(mk.ROOT, "examples", "diagnose")
SUFFIX = "_fit_rolling"
ROLLING = {"name": "mu_r_BP_BP", "property": "rolling_friction", "materials": ["BP", "BP"],
           "min": 0.01, "max": 0.5, "start": 0.1}


def write_study(case, folder=EXAMPLES, where=None):
    """folder/crossengine_<case>_fit_rolling.json from folder/crossengine_<case>.json."""
    study = json.load(open(os.path.join(folder, f"crossengine_{case}.json")))
    study["parameters"].append(dict(ROLLING))
    where = where or f"case {case} of datasets/liggghts_crossengine/"
    study["description"] = (
        f"Diagnosis on OTHER-ENGINE data: LIGGGHTS-made (not measured, not made by demcal), {where}, "
        "with the BP-BP rolling friction fitted in the base beside the sliding friction (demcal's cdt, "
        "from the assumed 0.10; the data's own law is LIGGGHTS' cdt); rig 1 (16 mm slot heap) at 0, "
        "1.5 and 3 wt% PEG, rig 2 (12.5 mm slot heap) at 0 and 3 wt%, the funnel and rig 3 (the narrow "
        "funnel) at 0 wt%. Written by scripts/liggghts_rolling_fitted_studies.py. Run with --quick, "
        "the fidelity the data were made at.")
    path = os.path.join(folder, f"crossengine_{case}{SUFFIX}.json")
    json.dump(study, open(path, "w"), indent=2)
    open(path, "a").write("\n")


def main():
    for case in mk.cases_from_arguments(__doc__.split("\n")[0]):
        write_study(case)


if __name__ == "__main__":
    main()
