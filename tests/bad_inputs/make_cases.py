#!/usr/bin/env python3
"""Writes the hostile-input corpus: one input file per case into files/ and the manifest
cases.txt (run by run_case.sh through ctest). Run it after editing a case:
    python3 tests/bad_inputs/make_cases.py
Each case: name, the files it needs, the demcal arguments ({files} = this folder's files/,
{out} = a fresh output directory), the expected exit code, a fragment the message must contain
and, optionally, one it must not contain."""
import copy, json, os, random, re, types

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = os.path.join(HERE, "files")

SCENE = {
    "format": "demcal-scene/1",
    "description": "bad_inputs base scene: 50 glass beads in a box",
    "seed": 1,
    "materials": [{"name": "glass", "youngs_modulus_Pa": 5.0e6, "poisson_ratio": 0.25,
                   "density_kg_m3": 2500}],
    "species": [{"name": "beads", "material": "glass", "diameter_m": 0.002}],
    "domain": {"min_m": [0, 0, 0], "max_m": [0.02, 0.02, 0.04]},
    "walls": [{"type": "plane", "point_m": [0, 0, 0], "normal": [0, 0, 1], "material": "glass"}],
    "fills": [{"species": "beads", "count": 50,
               "region": {"min_m": [0.001, 0.001, 0.001], "max_m": [0.019, 0.019, 0.03]}}],
    "time": {"duration_s": 0.01},
}
AOR = json.load(open(os.path.join(HERE, "..", "..", "examples", "aor_bp.json")))
STUDY = json.load(open(os.path.join(HERE, "..", "..", "examples", "calibrate_bp_rolling.json")))


def scene(**changes):
    s = copy.deepcopy(SCENE)
    for path, value in changes.items():
        node = s
        keys = path.split("__")
        for k in keys[:-1]:
            node = node[int(k)] if isinstance(node, list) else node[k]
        last = keys[-1]
        if value is DELETE:
            del node[last]
        elif isinstance(node, list):
            node[int(last)] = value
        else:
            node[last] = value
    return json.dumps(s, indent=1)


DELETE = object()
FACET = ("facet normal 0 0 1\n outer loop\n  vertex {a}\n  vertex {b}\n  vertex {c}\n"
         " endloop\nendfacet\n")


def facet(a, b, c):
    return FACET.format(a=a, b=b, c=c)


def mesh_scene(stl, offset=None):
    wall = {"type": "mesh", "file": stl, "material": "glass"}
    if offset:
        wall["offset_m"] = offset
    return scene(walls=SCENE["walls"] + [wall])


CASES = []  # (name, {file: content}, args, exit, fragment, absent)


def case(name, files, args, code, fragment, absent=""):
    CASES.append((name, files, args, code, fragment, absent))


S = "simulate {files}/%s --out {out}"
# --- scene files: size, depth, number syntax, file kind -------------------------------------
case("scene_deep_nesting", {"scene_deep_nesting.json": scene(description="@")
                            .replace('"@"', "[" * 100000 + "]" * 100000)},
     S % "scene_deep_nesting.json", 2, "description[0][0]", "internal error")
case("scene_depth_65", {"scene_depth_65.json": scene(description="@")
                        .replace('"@"', "[" * 64 + "]" * 64)},
     S % "scene_depth_65.json", 2, "nesting deeper than 64 levels")
case("scene_number_overflow", {"scene_number_overflow.json": scene(seed=1).replace(
    '"density_kg_m3": 2500', '"density_kg_m3": 1e999')},
     S % "scene_number_overflow.json", 2,
     "materials[0].density_kg_m3: number '1e999' is out of range", "internal error")
case("scene_huge_integer", {"scene_huge_integer.json": scene().replace(
    '"seed": 1', '"seed": 123456789012345678901234567890')},
     S % "scene_huge_integer.json", 2, "field 'seed' must be a non-negative integer")
case("scene_directory", {}, "simulate {files} --out {out}", 2, "it is a directory")
case("scene_dev_zero", {}, "simulate /dev/zero --out {out}", 2, "not a regular file")
case("scene_missing", {}, "simulate {files}/no_such_scene.json --out {out}", 2,
     "no_such_scene.json: cannot read the scene file: No such file or directory")
case("scene_empty", {"scene_empty.json": ""}, S % "scene_empty.json", 2, "invalid JSON")
case("scene_binary_junk", {"scene_binary_junk.json": bytes(random.Random(12).randrange(256)
                                                            for _ in range(3000))},
     S % "scene_binary_junk.json", 2, "invalid JSON")
case("scene_nan_literal", {"scene_nan_literal.json": scene().replace("0.25", "NaN")},
     S % "scene_nan_literal.json", 2, "invalid JSON")
case("scene_top_array", {"scene_top_array.json": "[1, 2, 3]"}, S % "scene_top_array.json", 2,
     "must be an object, got array")
case("scene_duplicate_key", {"scene_duplicate_key.json": scene().replace(
    '"seed": 1', '"seed": 1, "seed": 2')}, S % "scene_duplicate_key.json", 2,
     "key 'seed' appears twice")
case("scene_truncated_json", {"scene_truncated_json.json": scene()[:200]},
     S % "scene_truncated_json.json", 2, "invalid JSON: parse error")
case("scene_unknown_key", {"scene_unknown_key.json": scene(tiem={"duration_s": 1})},
     S % "scene_unknown_key.json", 2, "unknown key 'tiem'")
case("scene_string_number", {"scene_string_number.json": scene(
    materials__0__poisson_ratio="0.25")}, S % "scene_string_number.json", 2,
     "'materials[0].poisson_ratio' must be a number, got string")
case("scene_negative_density", {"scene_negative_density.json": scene(
    materials__0__density_kg_m3=-1)}, S % "scene_negative_density.json", 2,
     "'materials[0].density_kg_m3' is required (> 0)", "inf")
case("scene_youngs_zero", {"scene_youngs_zero.json": scene(materials__0__youngs_modulus_Pa=0)},
     S % "scene_youngs_zero.json", 2, "allowed range [1000, 1e+16] Pa", "inf")
case("scene_huge_count", {"scene_huge_count.json": scene(fills__0__count=10**12)},
     S % "scene_huge_count.json", 2, "fills[0].count", "e+299")
# --- cross-field checks ---------------------------------------------------------------------
FACTORY = {"species": [{"name": "beads", "mass_fraction": 1}], "mass_rate_kg_s": 0.001,
           "region": {"min_m": [0.001, 0.001, 0.03], "max_m": [0.019, 0.019, 0.039]}}
case("scene_batch_interval_tiny", {"scene_batch_interval_tiny.json": scene(
    factories=[dict(FACTORY, batch_interval_s=1e-30)])}, S % "scene_batch_interval_tiny.json", 2,
     "'factories[0].batch_interval_s' = 1e-30 s is shorter than the time step")
case("scene_too_many_steps", {"scene_too_many_steps.json": scene(
    time={"duration_s": 1e5, "timestep_s": 1e-6})}, S % "scene_too_many_steps.json", 2,
     "at most 1e+09 steps per run")
case("scene_too_many_snapshots", {"scene_too_many_snapshots.json": scene(
    time={"duration_s": 100}, output={"vtk_interval_s": 1e-6})},
     S % "scene_too_many_snapshots.json", 2, "at most 100000 snapshots per run")
case("scene_memory", {"scene_memory.json": scene(fills=[dict(SCENE["fills"][0], count=10**8)
                                                        for _ in range(40)])},
     S % "scene_memory.json", 2, "of memory (2400 bytes a sphere)")
case("scene_factory_mass_memory", {"scene_factory_mass_memory.json": scene(
    factories=[dict(FACTORY, mass_rate_kg_s=1e4, region={"min_m": [0, 0, 0.02],
                                                         "max_m": [0.02, 0.02, 0.04]})],
    domain={"min_m": [0, 0, 0], "max_m": [0.02, 0.02, 0.04]}, time={"duration_s": 1e3})},
     S % "scene_factory_mass_memory.json", 2, "factories")
case("scene_box_across_periodic", {"scene_box_across_periodic.json": scene(
    periodic={"x": True}, walls=[{"type": "box", "min_m": [0, 0, 0], "max_m": [0.02, 0.02, 0.04],
                                  "material": "glass"}])},
     S % "scene_box_across_periodic.json", 2, "crosses the periodic axis x")
# --- STL meshes -------------------------------------------------------------------------------
CUBE = "".join(facet(*f) for f in [("0 0 0", "0.01 0 0", "0 0.01 0"),
                                   ("0.01 0 0", "0.01 0.01 0", "0 0.01 0")])
case("stl_truncated", {"stl_truncated.stl": "solid cut\n" + facet("0 0 0", "0.01 0 0",
                                                                   "0 0.01 0"),
                       "stl_truncated.json": mesh_scene("stl_truncated.stl")},
     S % "stl_truncated.json", 2, "no final 'endsolid' after 1 facets")
case("stl_cut_mid_facet", {"stl_cut_mid_facet.stl": "solid cut\n" + CUBE[:120],
                           "stl_cut_mid_facet.json": mesh_scene("stl_cut_mid_facet.stl")},
     S % "stl_cut_mid_facet.json", 2, "truncated")
case("stl_far_vertex", {"stl_far_vertex.stl": "solid far\n" + facet("0 0 0", "1e305 0 0",
                                                                     "0 0.01 0") + "endsolid\n",
                        "stl_far_vertex.json": mesh_scene("stl_far_vertex.stl")},
     S % "stl_far_vertex.json", 2, "|coordinate| <= 1e+06 m")
case("stl_nan_vertex", {"stl_nan_vertex.stl": "solid n\n" + facet("0 0 0", "nan 0 0",
                                                                   "0 0.01 0") + "endsolid\n",
                        "stl_nan_vertex.json": mesh_scene("stl_nan_vertex.stl")},
     S % "stl_nan_vertex.json", 2, "non-finite")
case("stl_outside_domain", {"stl_outside_domain.stl": "solid o\n" + CUBE + "endsolid o\n",
                            "stl_outside_domain.json": mesh_scene("stl_outside_domain.stl",
                                                                  [1000, 0, 0])},
     S % "stl_outside_domain.json", 2, "lies entirely outside the domain along x")
case("stl_binary_short", {"stl_binary_short.stl": b"\0" * 80 + (7).to_bytes(4, "little")
                          + b"\1" * 120,
                          "stl_binary_short.json": mesh_scene("stl_binary_short.stl")},
     S % "stl_binary_short.json", 2, "stl_binary_short.stl")
case("stl_not_stl", {"stl_not_stl.stl": "hello, I am not a mesh\n",
                     "stl_not_stl.json": mesh_scene("stl_not_stl.stl")},
     S % "stl_not_stl.json", 2, "not an STL file")
case("stl_directory", {"stl_directory.json": mesh_scene(".")}, S % "stl_directory.json", 2,
     "not a regular file")
# --- experiment files ---------------------------------------------------------------------------
def aor(**changes):
    a = copy.deepcopy(AOR)
    for path, value in changes.items():
        node = a
        keys = path.split("__")
        for k in keys[:-1]:
            node = node[k]
        node[keys[-1]] = value
    return json.dumps(a, indent=1)


E = "experiment aor {files}/%s --out {out}"
case("exp_window_order", {"exp_window_order.json": aor(aor__angle={"window_low": 0.8,
                                                                    "window_high": 0.2})},
     E % "exp_window_order.json", 2, "field 'aor.angle.window_high' = 0.2 must exceed window_low",
     "ReposeAngleOptions")
case("exp_deep_nesting", {"exp_deep_nesting.json": aor(description="@")
                          .replace('"@"', "{\"a\":" * 50000 + "1" + "}" * 50000)},
     E % "exp_deep_nesting.json", 2, "nesting deeper than 64 levels")
case("exp_number_overflow", {"exp_number_overflow.json": aor().replace('"seed": 2018',
                                                                        '"seed": -1e400')},
     E % "exp_number_overflow.json", 2, "seed: number '-1e400' is out of range")
case("exp_wrong_kind", {"exp_wrong_kind.json": aor()},
     "experiment discharge {files}/exp_wrong_kind.json --out {out}", 2,
     "exp_wrong_kind.json is an 'aor' experiment file, not 'discharge'; run it with `demcal "
     "experiment aor`")
case("exp_replicates_zero", {"exp_replicates_zero.json": aor(replicates=0)},
     E % "exp_replicates_zero.json", 2, "'replicates' = 0 is outside the allowed range [1, 1000]")
case("exp_dev_zero", {}, "experiment aor /dev/zero --out {out}", 2, "not a regular file")
case("exp_feed_mass_nan", {"exp_feed_mass_nan.json": aor().replace('"mass_kg": 0.0025',
                                                                    '"mass_kg": "NaN"')},
     E % "exp_feed_mass_nan.json", 2, "'aor.feed.mass_kg' must be a number")
# --- study files and measurement tables -------------------------------------------------------
def study(**changes):
    s = copy.deepcopy(STUDY)
    s["experiment_file"] = "../../../examples/aor_bp.json"
    s["measurement"]["dataset"] = "../../../datasets/alizadeh2018/measurements.csv"
    for k, v in changes.items():
        s[k] = v
    return json.dumps(s, indent=1)


def nesting_and_overflow(kind, make, command):
    """Two cases every JSON file kind gets: a 100,000-deep description and a 1e999 number."""
    case(kind + "_deep_nesting", {kind + "_deep_nesting.json": make(description="@")
                                  .replace('"@"', "[" * 100000 + "]" * 100000)},
         command % (kind + "_deep_nesting.json"), 2, "nesting deeper than 64 levels")
    overflow = re.sub(r'"replicates": 2\b', '"replicates": 1e999', make(replicates=2), count=1)
    case(kind + "_overflow", {kind + "_overflow.json": overflow}, command % (kind + "_overflow.json"),
         2, "replicates: number '1e999' is out of range")


C = "calibrate {files}/%s --out {out} --max-evaluations 1"
nesting_and_overflow("study", study, C)
case("study_directory", {}, "calibrate {files} --out {out}", 2, "it is a directory")
HEADER = "observable,unit,material,coating_PEG_wt_pct,test,value,uncertainty,repeats,provenance,source\n"
ROW = "angle_deg,deg,BP,0,pseudo-2D heap,{v},,,measured,test\n"


def table_case(name, text, fragment):
    s = json.loads(study())
    s["measurement"]["dataset"] = name + ".csv"
    case(name, {name + ".csv": text, name + ".json": json.dumps(s, indent=1)},
         C % (name + ".json"), 2, fragment)


table_case("table_angle_400", HEADER + ROW.format(v=400), "400")
table_case("table_duplicate_rows", HEADER + ROW.format(v=40) + ROW.format(v=41), "line")
table_case("table_not_a_number", HEADER + ROW.format(v="forty"), "forty")
table_case("table_overflow", HEADER + ROW.format(v="1e999"), "value")
table_case("table_hex_value", HEADER + ROW.format(v="0x1p5"),
           "value: '0x1p5' is not a finite decimal number")
table_case("table_value_twice", HEADER.replace("source\n", "source,value\n") +
           ROW.replace("test\n", "test,41\n").format(v=40),
           "column 'value' appears twice (columns 6 and 11)")
case("study_clump_count_wraps", {"study_clump_count_wraps.json": study(clump_count={
    "species": "BP", "semi_axes": [1.5, 1, 1], "counts": [1, 4294967297]})},
     C % "study_clump_count_wraps.json", 2,
     "'clump_count.counts[1]' = 4294967297 is outside the allowed range [1, ")
case("study_format_mixed", {"study_format_mixed.json": study(targets=[])},
     C % "study_format_mixed.json", 2,
     "field 'targets' is a demcal-study/2 key, but this file is demcal-study/1")
# --- command line -----------------------------------------------------------------------------
case("cli_unknown_command", {}, "frobnicate", 2, "unknown command 'frobnicate'")
case("cli_no_command", {}, "", 2, "subcommand")
case("scene_particles_coincident", {"scene_particles_coincident.json": scene(
    fills=[], particles=[{"species": "beads", "position_m": [0.01, 0.01, 0.01]},
                         {"species": "beads", "position_m": [0.0101, 0.01, 0.01]}])},
     S % "scene_particles_coincident.json", 2,
     "field 'particles[0]' and 'particles[1]': centres 0.0001 m apart, inside one another")
# --- walls across periodic axes: every shape, not only planes ------------------------------
PERIODIC_X = {"x": True}
case("scene_cylinder_across_periodic", {"scene_cylinder_across_periodic.json": scene(
    periodic=PERIODIC_X, walls=SCENE["walls"] + [{"type": "cylinder", "axis_point_m": [0.01, 0.01, 0],
                                                  "axis": [0, 0, 1], "radius_m": 0.012, "material": "glass"}])},
     S % "scene_cylinder_across_periodic.json", 2,
     "crosses the periodic axis x: it reaches [-0.002, 0.022] m along x")
case("scene_cone_across_periodic", {"scene_cone_across_periodic.json": scene(
    periodic={"y": True}, walls=SCENE["walls"] + [{"type": "cone", "axis_point_m": [0.01, 0.01, 0],
                                                  "axis": [0, 0, 1], "height0_m": 0.005, "radius0_m": 0.002,
                                                  "height1_m": 0.03, "radius1_m": 0.011,
                                                  "material": "glass"}])},
     S % "scene_cone_across_periodic.json", 2, "crosses the periodic axis y")
case("scene_tilted_cylinder_periodic", {"scene_tilted_cylinder_periodic.json": scene(
    periodic=PERIODIC_X, walls=SCENE["walls"] + [{"type": "cylinder", "axis_point_m": [0.01, 0.01, 0],
                                                  "axis": [0.6, 0, 0.8], "radius_m": 0.004,
                                                  "material": "glass"}])},
     S % "scene_tilted_cylinder_periodic.json", 2, "is unbounded along x")
case("scene_moving_cylinder_periodic", {"scene_moving_cylinder_periodic.json": scene(
    periodic=PERIODIC_X, walls=SCENE["walls"] + [{"type": "cylinder", "axis_point_m": [0.01, 0.01, 0],
                                                  "axis": [0, 0, 1], "radius_m": 0.003, "axial_max_m": 0.03,
                                                  "velocity_m_s": [1, 0, 0], "material": "glass"}])},
     S % "scene_moving_cylinder_periodic.json", 2, "crosses the periodic axis x")
case("stl_across_periodic", {"stl_across_periodic.json": scene(
    periodic=PERIODIC_X, walls=SCENE["walls"] + [{"type": "mesh", "file": "stl_far_wide.stl",
                                                  "material": "glass"}]),
    "stl_far_wide.stl": "solid w\n" + facet("-0.01 0 0.01", "0.03 0 0.01", "0 0.02 0.01") +
                         "endsolid w\n"},
     S % "stl_across_periodic.json", 2, "crosses the periodic axis x: it reaches [-0.01, 0.03] m")
case("cli_progress_zero", {}, "simulate {files}/scene_empty.json --out {out} "
     "--progress-interval-s 0", 2, "(0, 1e+06] s", "00000000000")
case("cli_checkpoint_negative", {}, "simulate {files}/scene_empty.json --out {out} "
     "--checkpoint-every-s -1", 2, "[0, 1e+06] s")
case("cli_threads_huge", {}, "simulate {files}/scene_empty.json --out {out} --threads 99999999",
     2, "threads")
case("cli_restart_missing", {"cli_restart_missing.json": scene()},
     "simulate {files}/cli_restart_missing.json --out {out} --restart {files}/no_such.bin", 2,
     "no_such.bin")
case("cli_out_is_file", {}, "simulate {files}/scene_top_array.json --out "
     "{files}/scene_top_array.json", 2, "Not a directory")

# --- workflow files (demcal reproduce) and diagnose ----------------------------------------
WORKFLOW = json.load(open(os.path.join(HERE, "..", "..", "datasets", "alizadeh2018", "workflow.json")))


def workflow(edit=None, **changes):
    """The bundled workflow with its paths made relative to files/, then changed."""
    w = copy.deepcopy(WORKFLOW)
    up = "../../../datasets/alizadeh2018/"
    w["measurements"] = up + w["measurements"]
    w["synthetic_measurements"] = up + w["synthetic_measurements"]
    for s in w["species"]:
        s["experiment_file"] = up + s["experiment_file"]
    w["coating"]["experiment_file"] = up + w["coating"]["experiment_file"]
    w["segregation"]["experiment_file"] = up + w["segregation"]["experiment_file"]
    w.update(changes)
    if edit:
        edit(w)
    return json.dumps(w, indent=1)


R = "reproduce {files}/%s --out {out}"
nesting_and_overflow("workflow", workflow, R)
case("workflow_wrong_format", {"workflow_wrong_format.json": workflow(format="demcal-workflow/9")},
     R % "workflow_wrong_format.json", 2, "demcal-workflow/1")
case("workflow_unknown_key", {"workflow_unknown_key.json": workflow(replicats=3)},
     R % "workflow_unknown_key.json", 2, "replicats")
case("workflow_level_negative", {"workflow_level_negative.json": workflow(
    lambda w: w["coating"].update(levels_wt_pct=[0.5, -1]))},
     R % "workflow_level_negative.json", 2, "coating.levels_wt_pct[1]")
case("workflow_species_bounds", {"workflow_species_bounds.json": workflow(
    lambda w: w["species"][0].update(min=0.9, max=0.1, start=0.5))},
     R % "workflow_species_bounds.json", 2, "species[0]")
case("workflow_aspect_ratio_below_sphere", {"workflow_aspect_ratio_below_sphere.json": workflow(
    lambda w: w["species"][0].update(hold=True, clump_counts=[1, 2],
                                     aspect_ratio={"min": 0.5, "max": 3.5}))},
     R % "workflow_aspect_ratio_below_sphere.json", 2,
     "species[0].aspect_ratio.min' = 0.5 is outside the allowed range [1, 10]")
case("workflow_poisson", {"workflow_poisson.json": workflow(
    lambda w: w["cohesion"].update(poisson_ratio=0.7))},
     R % "workflow_poisson.json", 2, "cohesion.poisson_ratio")
case("workflow_string_number", {"workflow_string_number.json": workflow(
    lambda w: w["cohesion"].update(youngs_real_Pa="1.6e9"))},
     R % "workflow_string_number.json", 2, "cohesion.youngs_real_Pa")
case("workflow_reference_key", {"workflow_reference_key.json": workflow(
    lambda w: w["reference"][0].update(key="angle_of_everything"))},
     R % "workflow_reference_key.json", 2, "angle_of_everything")
case("workflow_missing_experiment", {"workflow_missing_experiment.json": workflow(
    lambda w: w["species"][0].update(experiment_file="no_such_aor.json"))},
     R % "workflow_missing_experiment.json", 2, "no_such_aor.json")
case("workflow_missing_table", {"workflow_missing_table.json": workflow(measurements="no_such.csv")},
     R % "workflow_missing_table.json", 2, "no_such.csv")
case("workflow_directory", {}, "reproduce {files} --out {out}", 2, "directory")
case("workflow_unknown_name", {}, "reproduce no_such_workflow --out {out}", 2, "no_such_workflow")
D = "diagnose {files}/%s --out {out} --quick"
case("diagnose_deep_nesting", {}, D % "study_deep_nesting.json", 2, "nesting deeper than 64 levels")
case("diagnose_significance", {}, D % "study_overflow.json" + " --significance 2", 2,
     "significance")
case("diagnose_unknown_effect", {"diagnose_study.json": study()},
     D % "diagnose_study.json" + " --effects jkr_adhesion,telekinesis", 2, "telekinesis")
case("diagnose_refits_negative", {}, D % "diagnose_study.json" + " --refits -1", 2, "refits")
case("diagnose_significance_nan", {}, D % "diagnose_study.json" + " --significance nan", 2,
     "--significance: 'nan' is not a number in (0, 0.5)")
case("diagnose_floor_nan", {}, D % "diagnose_study.json" + " --discrepancy-floor nan", 2,
     "--discrepancy-floor: 'nan' is not a number in [0, 10]")
case("cohesion_gamma_range", {}, "cohesion --gamma-J-m2 200", 2,
     "--gamma-J-m2: '200' is not a number in (0, 100] J/m2", "100.000000")
table_case("table_byte_order_mark_ok", ("\ufeff" + HEADER + ROW.format(v=400)).encode(),
           "value: 400")
case("diagnose_directory", {}, "diagnose {files} --out {out}", 2, "directory")
import study_cases  # noqa: E402 (studies that could never evaluate a candidate)
study_cases.add(case)
study_cases.add_workflow(case, workflow)
study_cases.add_ranges(case, study, scene, SCENE["walls"])

import magnitude_cases  # noqa: E402 (magnitudes that are finite but not physical)
magnitude_cases.add(case, types.SimpleNamespace(scene=scene, study=study, table_case=table_case,
                                                S=S, C=C, FACTORY=FACTORY, HEADER=HEADER, ROW=ROW))

# Not cases: the scenes of checkpoint_test.sh (a base run, and others its checkpoint must not fit).
CHECKPOINT_SCENES = {
    "checkpoint_base.json": scene(),
    "checkpoint_other_scene.json": scene(fills__0__count=60),
    "checkpoint_other_dt.json": scene(time={"duration_s": 0.01, "timestep_s": 1e-5}),
    "checkpoint_other_gravity.json": scene(gravity_m_s2=[0, 0, -9.0]),
}
# Not a case: a valid scene in a closed box that runs for a while (lock_test.sh).
LONG_RUN = scene(walls=[{"type": "box", "min_m": [0, 0, 0], "max_m": [0.02, 0.02, 0.04],
                         "material": "glass"}], time={"duration_s": 20})


def main():
    os.makedirs(FILES, exist_ok=True)
    for f in os.listdir(FILES):
        os.remove(os.path.join(FILES, f))
    with open(os.path.join(FILES, "long_run.json"), "w") as out:
        out.write(LONG_RUN)
    for fname, content in CHECKPOINT_SCENES.items():
        with open(os.path.join(FILES, fname), "w") as out:
            out.write(content)
    lines = ["# tab-separated: name, demcal arguments, exit code, message fragment, must not contain",
             "# generated by make_cases.py; {files} = tests/bad_inputs/files, {out} = scratch dir"]
    for name, files, args, code, fragment, absent in CASES:
        for fname, content in files.items():
            mode = "wb" if isinstance(content, bytes) else "w"
            with open(os.path.join(FILES, fname), mode) as out:
                out.write(content)
        for field in (args, fragment, absent):
            assert "\t" not in field, name
        lines.append("\t".join([name, args, str(code), fragment, absent]))
    with open(os.path.join(HERE, "cases.txt"), "w") as out:
        out.write("\n".join(lines) + "\n")
    print(len(CASES), "cases")


main()
