"""Cases of make_cases.py: magnitudes that are finite but not physical, refused against the one
table of ranges (core/limits/physical_limits.h) naming the field and the allowed range."""
import json


def add(case, b):
    """b: make_cases' builders (scene, study, table_case) and constants (S, C, FACTORY, HEADER,
    ROW)."""
    scene, study, table_case = b.scene, b.study, b.table_case
    S, C, FACTORY, HEADER, ROW = b.S, b.C, b.FACTORY, b.HEADER, b.ROW
    case("scene_gravity_huge", {"scene_gravity_huge.json": scene(gravity_m_s2=[0, 0, -1e308])},
         S % "scene_gravity_huge.json", 2,
         "field 'gravity_m_s2' has magnitude 1e+308 m/s2, outside the allowed range [0, 10000] m/s2")
    case("scene_velocity_huge", {"scene_velocity_huge.json": scene(
        fills=[], particles=[{"species": "beads", "position_m": [0.01, 0.01, 0.01],
                              "velocity_m_s": [1e308, 0, 0]}])},
         S % "scene_velocity_huge.json", 2,
         "field 'particles[0].velocity_m_s' has magnitude 1e+308 m/s, outside the allowed range")
    # 100 m/s is a possible speed, but 2.4 mm per time step for beads of radius 1 mm.
    case("scene_fill_speed_per_step", {"scene_fill_speed_per_step.json": scene(
        fills__0__velocity_m_s=[0, 0, -100])}, S % "scene_fill_speed_per_step.json", 2,
         "field 'fills[0].velocity_m_s': a speed of 100 m/s")
    case("scene_wall_speed_huge", {"scene_wall_speed_huge.json": scene(
        walls__0__velocity_m_s=[0, 0, 1e308])}, S % "scene_wall_speed_huge.json", 2,
         "field 'walls[0].velocity_m_s' has magnitude 1e+308 m/s")
    case("scene_factory_region_velocity_huge", {"scene_factory_region_velocity_huge.json": scene(
        factories=[dict(FACTORY, region_velocity_m_s=[1e308, 0, 0])])},
         S % "scene_factory_region_velocity_huge.json", 2,
         "field 'factories[0].region_velocity_m_s' has magnitude 1e+308 m/s")
    case("scene_factory_region_leaves", {"scene_factory_region_leaves.json": scene(
        factories=[dict(FACTORY, region_velocity_m_s=[2, 0, 0])])},
         S % "scene_factory_region_leaves.json", 2,
         "field 'factories[0].region_velocity_m_s' moves the region by 0.02 m")
    case("scene_factory_velocity_huge", {"scene_factory_velocity_huge.json": scene(
        factories=[dict(FACTORY, velocity_m_s=[0, 0, -1e308])])},
         S % "scene_factory_velocity_huge.json", 2,
         "field 'factories[0].velocity_m_s' has magnitude 1e+308 m/s")
    case("scene_clump_semi_axes", {"scene_clump_semi_axes.json": scene(species=[{
        "name": "beads", "material": "glass", "diameter_m": 0.002,
        "clump": {"ellipsoid": {"semi_axes": [1e300, 1, 1e-300], "sphere_count": 3}}}])},
         S % "scene_clump_semi_axes.json", 2,
         "'species[0].clump.ellipsoid.semi_axes' = [1e+300, 1, 1e-300] is outside the allowed range "
         "[1e-09, 1e+09]")
    case("scene_clump_needle", {"scene_clump_needle.json": scene(species=[{
        "name": "beads", "material": "glass", "diameter_m": 0.002,
        "clump": {"ellipsoid": {"semi_axes": [50, 1, 1], "sphere_count": 5}}}])},
         S % "scene_clump_needle.json", 2, "aspect ratio a/c = 50, outside the allowed range [1, 10]")
    case("scene_wall_point_far", {"scene_wall_point_far.json": scene(
        walls__0__point_m=[0, 0, -1e300])}, S % "scene_wall_point_far.json", 2,
         "'walls[0].point_m[2]' = -1e+300 m is outside the allowed range [-1e+06, 1e+06] m")
    case("scene_youngs_huge", {"scene_youngs_huge.json": scene(materials__0__youngs_modulus_Pa=1e300)},
         S % "scene_youngs_huge.json", 2,
         "'materials[0].youngs_modulus_Pa' = 1e+300 is outside the allowed range [1000, 1e+16] Pa")
    case("study_clump_semi_axes", {"study_clump_semi_axes.json": study(clump_count={
        "species": "BP", "semi_axes": [1e300, 1, 1e-300], "counts": [1, 2]})},
         C % "study_clump_semi_axes.json", 2,
         "'clump_count.semi_axes' = [1e+300, 1, 1e-300] is outside the allowed range [1e-09, 1e+09]")
    table_case("table_uncertainty_tiny", HEADER + ROW.replace("{v},,", "{v},1e-320,").format(v=40),
               "uncertainty: '1e-320'; allowed: empty or a number in [9e-11, 90] deg")


    def stated_uncertainty():
        s = json.loads(study())
        s["measurement"]["uncertainty_deg"] = 1e-320
        return json.dumps(s, indent=1)


    case("study_uncertainty_tiny", {"study_uncertainty_tiny.json": stated_uncertainty()},
         C % "study_uncertainty_tiny.json", 2,
         "deg is outside the allowed range [9e-11, 90] deg for angle_deg")
