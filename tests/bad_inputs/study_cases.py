"""Cases of make_cases.py: studies that parse but could never evaluate a candidate, or hold a
parameter that never acts. Each must be refused at load, naming the field."""
import copy, json, os

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")
C = "calibrate {files}/%s --out {out} --max-evaluations 1"


def example(name):
    """An example study with its paths made relative to files/."""
    s = json.load(open(os.path.join(EXAMPLES, name)))
    s["measurements"] = "../../../examples/" + s["measurements"]
    for t in s["targets"]:
        t["experiment_file"] = "../../../examples/" + t["experiment_file"]
    return s


CURVE = example("calibrate_bp_gamma_curve.json")
LEVELS = example("calibrate_bp_gamma_per_level.json")


def add(case):
    def study_case(name, base, edit, fragment):
        s = copy.deepcopy(base)
        edit(s)
        case(name, {name + ".json": json.dumps(s, indent=1)}, C % (name + ".json"), 2, fragment)

    def curve(**changes):
        return lambda s: s["parameters"][0]["curve"].update(changes)

    study_case("study_curve_no_covariate", CURVE, curve(covariate="coating_wt_pct"),
               "field 'parameters[0].curve.covariate' 'coating_wt_pct' cannot be read for target "
               "'angle_deg BP (coating_PEG_wt_pct=1, test=pseudo-2D heap)'")
    study_case("study_curve_word_covariate", CURVE, curve(covariate="test"),
               "gives 'test' a word, 'pseudo-2D heap', not a number")

    def power_law_at_zero(s):
        s["parameters"][0]["curve"].update(form="power_law")
        s["targets"][0]["measurement"]["conditions"]["coating_PEG_wt_pct"] = 0
        s["measurements"] = "../../../datasets/alizadeh2018/measurements.csv"
        s["targets"] = [t for t in s["targets"][:1]]
        s["targets"][0]["measurement"]["uncertainty"] = 1
    study_case("study_power_law_at_zero", CURVE, power_law_at_zero,
               "a power law needs coating_PEG_wt_pct > 0 (the condition gives 0)")
    study_case("study_curve_start_negative", CURVE,
               lambda s: s["parameters"][0]["curve"]["coefficients"][0].update(start=-0.02),
               "field 'parameters[0].curve.coefficients' start values fail")

    def restitution_after_curve(s):  # the space's third parameter is the file's second
        s["parameters"].append({"name": "e_BP", "property": "restitution",
                                "materials": ["BP", "BP"], "min": 0.1, "max": 2})
    study_case("study_bounds_after_curve", CURVE, restitution_after_curve,
               "parameters[1].min/max: need min < max within [0, 1] (got [0.1, 2])")

    def add_global_gamma(s):
        s["parameters"].append({"name": "gamma_BP", "property": "interfacial_energy_J_m2",
                                "materials": ["BP", "BP"], "min": 0, "max": 0.04})
    study_case("study_curve_and_global", CURVE, add_global_gamma,
               "field 'parameters[1]' sets the pair property that the curve 'gamma_BP_BP' "
               "(parameters[0].curve) overwrites for every target, so it would never act")
    study_case("study_when_no_target", LEVELS,
               lambda s: s["parameters"][2]["when"].update(coating_PEG_wt_pct=7),
               "field 'parameters[2].when' (coating_PEG_wt_pct=7) is the condition of no target")

    study_case("study_when_then_global", LEVELS, add_global_gamma,
               "field 'parameters[0]' sets the pair property that 'gamma_BP' (parameters[3]) sets "
               "again wherever this one applies")
    def bounds_apart(s):
        s["parameters"][0].update(min=0.01, start=0.02)
        s["parameters"][2].update(max=0.004, start=0.002)
    study_case("study_non_decreasing_bounds", LEVELS, bounds_apart,
               "field 'constraints[0].non_decreasing' cannot hold within the bounds: 'gamma_w3' "
               "(max 0.004) would have to be >= 'gamma_w1' (min 0.01)")
    study_case("study_non_decreasing_start", LEVELS,
               lambda s: s["parameters"][0].pop("start"),
               "field 'constraints[0].non_decreasing' the start values break it: 'gamma_w2' "
               "starts at 0.015, below 'gamma_w1' at 0.02")


def add_workflow(case, workflow):
    """Workflow files refused as a whole before stage 1, naming the workflow's own field."""
    R = "reproduce {files}/%s --out {out}"
    synthetic = os.path.join(EXAMPLES, "..", "datasets", "synthetic",
                             "alizadeh2018_coating_angles", "measurements.csv")

    def workflow_case(name, edit, fragment, files=None):
        files = dict(files or {})
        files[name + ".json"] = workflow(edit)
        case(name, files, R % (name + ".json"), 2, fragment, "study.json")

    workflow_case("workflow_species_twice", lambda w: w["species"].append(w["species"][0]),
                  "field 'species[3].name' 'BP' is the species of species[0] too")
    workflow_case("workflow_level_twice",
                  lambda w: w["coating"].update(levels_wt_pct=[0.5, 1.5, 0.50]),
                  "field 'coating.levels_wt_pct[2]' = 0.5 repeats levels_wt_pct[0]")
    workflow_case("workflow_reference_twice", lambda w: w["reference"].append(w["reference"][0]),
                  "'angle_BP_deg' is the key of reference[0] too")
    workflow_case("workflow_partner_unknown",
                  lambda w: w["coating"].update(partners=["BP", "TEAD"]),
                  "field 'coating.partners[1]' 'TEAD' is not a material of")
    workflow_case("workflow_coated_unknown", lambda w: w["coating"].update(material="PE"),
                  "field 'coating.material' 'PE' is not a material of")
    workflow_case("workflow_species_unknown", lambda w: w["species"][2].update(name="EPP"),
                  "field 'species[2]' ('EPP'): its calibration would be refused: ")
    measured = open(synthetic).read().replace(",synthetic,", ",measured,", 1)
    workflow_case("workflow_synthetic_measured",
                  lambda w: w.update(synthetic_measurements="workflow_synthetic_measured.csv"),
                  "workflow_synthetic_measured.csv' line 2 has provenance 'measured'",
                  {"workflow_synthetic_measured.csv": measured})


def add_ranges(case, study, scene, base_walls):
    """Numbers in messages with 6 significant digits (FormatNumber, Limit::Text), never the
    six decimals of std::to_string."""
    C1 = "calibrate {files}/%s --out {out} --max-evaluations 1"
    case("study_restitution_above_one", {"study_restitution_above_one.json": study(parameters=[
        {"name": "e_BP", "property": "restitution", "materials": ["BP", "BP"], "min": 0.1,
         "max": 2}])}, C1 % "study_restitution_above_one.json", 2,
         "parameters[0].min/max: need min < max within [0, 1] (got [0.1, 2])", "000000")
    case("scene_cylinder_axial_order", {"scene_cylinder_axial_order.json": scene(
        walls=base_walls + [{"type": "cylinder", "axis_point_m": [0.01, 0.01, 0],
                             "axis": [0, 0, 1], "radius_m": 0.005, "axial_min_m": 0.02,
                             "axial_max_m": 0.01, "material": "glass"}])},
         "simulate {files}/scene_cylinder_axial_order.json --out {out}", 2,
         "(0.02 >= 0.01)", "000000")
