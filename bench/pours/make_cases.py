#!/usr/bin/env python3
"""make_cases.py -- writes the inputs of bench/compare_pours.sh for BOTH codes from one set of
parameters, so demcal and LIGGGHTS run the same cases:

  heap       a conical heap poured from a narrow stream (cylinder, radius 5 mm, 60 mm above the
             base, 1.5 m/s down, 0.06 kg/s) onto a frozen rough base (a disc of fixed 2 mm spheres
             at 2 mm pitch, each lifted at random by up to half a radius, as demcal_bench pour);
             the run lasts until the last sphere was inserted plus 0.1 s
  discharge  a flat-bottomed cylindrical silo (R 25 mm) whose bottom is an STL mesh with a
             16 mm orifice, filled at t = 0 (random loose packing in the silo), plugged by a plane
             until t_open, then discharging for 1.2 s; grains leaving 5 cm below the orifice are
             removed (demcal: a sink; LIGGGHTS: the fixed domain boundary, lost atoms ignored)

Spheres: d in {1.8, 1.9, 2.0, 2.1, 2.2} mm, equal number fractions; rho 2500 kg/m3, E 5 MPa,
nu 0.25, e 0.5, mu_s 0.5, mu_r 0.1 (epsd2), walls the same material; dt 2.4e-5 s; skin 0.5 mm.

  make_cases.py OUT_DIR [--quick]

Writes OUT_DIR/{heap.json, heap_base.data, heap.vars, discharge.json, bottom.stl, discharge.vars}.
*.json are demcal scenes; *.data, *.stl and *.vars (LIGGGHTS "-var name value" arguments, one
pair per line) are read by bench/pours/in.heap and in.discharge. --quick: 1,500 poured spheres
and a 2,000-sphere silo with 0.2 s of discharge (to check the script, not to time).
"""
import json
import math
import random
import sys

DIAMETERS = [0.0018, 0.0019, 0.0020, 0.0021, 0.0022]
DENSITY = 2500.0
MEAN_MASS = DENSITY * math.pi / 6 * sum(d ** 3 for d in DIAMETERS) / len(DIAMETERS)
DT = 2.4e-5
SKIN = 0.0005


def material_block():
    return {
        "materials": [{"name": "glass", "youngs_modulus_Pa": 5e6, "poisson_ratio": 0.25,
                       "density_kg_m3": DENSITY}],
        "species": [{"name": "beads", "material": "glass", "diameter_table": [
            {"diameter_m": d, "number_fraction": 1.0 / len(DIAMETERS)} for d in DIAMETERS]}],
        "interactions": {"default": {"sliding_friction": 0.5, "rolling_friction": 0.1,
                                     "restitution": 0.5}},
        "contact_model": {"rolling": "epsd2"},
    }


def write_vars(path, values):
    with open(path, "w") as f:
        for k, v in values.items():
            f.write(f"{k} {v}\n")


def heap(out, quick):
    n = 1500 if quick else 15000
    base_r, rate, stream_top = 0.097, 0.06, 0.06
    half, top = base_r + 0.01, stream_top + 0.02
    duration = n * MEAN_MASS / rate + 0.1
    steps = int(round(duration / DT))
    rng = random.Random(77)
    d = 0.002
    k = int(math.floor(2 * base_r / d))
    base = []
    for i in range(k):
        for j in range(k):
            x, y = (i - 0.5 * (k - 1)) * d, (j - 0.5 * (k - 1)) * d
            z = 0.5 * d * (1 + 0.5 * rng.random())
            if x * x + y * y <= base_r * base_r:
                base.append((x, y, z))
    with open(f"{out}/heap_base.data", "w") as f:
        f.write("frozen rough base of bench/pours heap (make_cases.py)\n\n")
        f.write(f"{len(base)} atoms\n2 atom types\n\n")
        f.write(f"{-half} {half} xlo xhi\n{-half} {half} ylo yhi\n0 {top + 0.02} zlo zhi\n\n")
        f.write("Atoms\n\n")
        for a, (x, y, z) in enumerate(base, 1):
            f.write(f"{a} 2 {d} {DENSITY} {x:.9g} {y:.9g} {z:.9g}\n")
    scene = {"format": "demcal-scene/1",
             "description": f"bench/pours heap: {n} spheres poured onto a frozen base of "
                            f"{len(base)} (make_cases.py)",
             "seed": 1}
    scene.update(material_block())
    scene["domain"] = {"min_m": [-half, -half, 0], "max_m": [half, half, top + 0.02]}
    scene["walls"] = [{"type": "box", "name": "box", "material": "glass",
                       "min_m": [-half, -half, 0], "max_m": [half, half, top], "open_top": True}]
    scene["particles"] = [{"species": "beads", "position_m": [x, y, z], "diameter_m": d,
                           "fixed": True} for x, y, z in base]
    scene["factories"] = [{"name": "stream", "species": [{"name": "beads"}],
                           "mass_rate_kg_s": rate, "total_mass_kg": n * MEAN_MASS,
                           "velocity_m_s": [0, 0, -1.5],
                           "region": {"shape": "cylinder", "axis_point_m": [0, 0, 0],
                                      "radius_m": 0.005,
                                      "z_range_m": [stream_top - 0.02, stream_top]}}]
    scene["time"] = {"duration_s": steps * DT, "timestep_s": DT}
    scene["skin_m"] = SKIN
    with open(f"{out}/heap.json", "w") as f:
        json.dump(scene, f, indent=1)
    write_vars(f"{out}/heap.vars", {"nparticles": n, "massrate": rate, "nsteps": steps,
                                    "half": half, "top": top, "ztop": stream_top,
                                    "zbottom": stream_top - 0.02})
    return len(base), n, steps


def stl_annulus(path, r_in, r_out, segments=64):
    with open(path, "w") as f:
        f.write("solid bottom\n")
        for s in range(segments):
            a0, a1 = 2 * math.pi * s / segments, 2 * math.pi * (s + 1) / segments
            p = [(r_in * math.cos(a0), r_in * math.sin(a0)), (r_out * math.cos(a0), r_out * math.sin(a0)),
                 (r_out * math.cos(a1), r_out * math.sin(a1)), (r_in * math.cos(a1), r_in * math.sin(a1))]
            for tri in ((p[0], p[1], p[2]), (p[0], p[2], p[3])):
                f.write("  facet normal 0 0 1\n    outer loop\n")
                for x, y in tri:
                    f.write(f"      vertex {x:.9g} {y:.9g} 0\n")
                f.write("    endloop\n  endfacet\n")
        f.write("endsolid bottom\n")


def discharge(out, quick):
    n = 2000 if quick else 15000
    radius, orifice_r, height = 0.025, 0.008, 0.2
    fill_top = 0.06 if quick else 0.19
    t_open = 0.3 if quick else 0.4
    duration = t_open + (0.2 if quick else 1.2)
    stl_annulus(f"{out}/bottom.stl", orifice_r, radius + 0.005)
    scene = {"format": "demcal-scene/1",
             "description": f"bench/pours discharge: {n} spheres, silo R {radius} m, STL bottom "
                            f"with a {2 * orifice_r} m orifice opened at {t_open} s (make_cases.py)",
             "seed": 1}
    scene.update(material_block())
    scene["domain"] = {"min_m": [-0.03, -0.03, -0.06], "max_m": [0.03, 0.03, height]}
    scene["walls"] = [
        {"type": "cylinder", "name": "silo", "material": "glass", "axis_point_m": [0, 0, 0],
         "axis": [0, 0, 1], "radius_m": radius, "axial_min_m": 0, "axial_max_m": height,
         "shell": False, "inside": True},
        {"type": "mesh", "name": "bottom", "material": "glass", "file": "bottom.stl"},
        {"type": "plane", "name": "plug", "material": "glass", "point_m": [0, 0, 0],
         "normal": [0, 0, 1], "remove_at_s": t_open}]
    scene["fills"] = [{"species": "beads", "count": n,
                       "region": {"shape": "cylinder", "axis_point_m": [0, 0, 0],
                                  "radius_m": radius - 0.0012, "z_range_m": [0.0012, fill_top]}}]
    scene["sinks"] = [{"name": "below", "shape": "plane", "point_m": [0, 0, -0.05],
                       "normal": [0, 0, -1]}]
    steps_fill = int(round(t_open / DT))
    steps_discharge = int(round((duration - t_open) / DT))
    scene["time"] = {"duration_s": (steps_fill + steps_discharge) * DT, "timestep_s": DT}
    scene["skin_m"] = SKIN
    with open(f"{out}/discharge.json", "w") as f:
        json.dump(scene, f, indent=1)
    write_vars(f"{out}/discharge.vars", {"nparticles": n, "radius": radius,
                                         "fill_radius": radius - 0.0012, "fill_top": fill_top,
                                         "height": height, "steps_fill": steps_fill,
                                         "steps_discharge": steps_discharge})
    return n, steps_fill + steps_discharge


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out, quick = sys.argv[1], "--quick" in sys.argv[2:]
    b, n, s = heap(out, quick)
    print(f"heap: {b} base spheres, {n} poured, {s} steps")
    m, t = discharge(out, quick)
    print(f"discharge: {m} spheres, {t} steps")
