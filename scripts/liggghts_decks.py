"""LIGGGHTS 3.8 decks for the diagnosis rig (the heap of examples/diagnose/aor_bp_heap.json and the
funnel of examples/diagnose/discharge_bp_small.json), written from a Model that mirrors a demcal
experiment file at quick fidelity. Used by scripts/make_liggghts_datasets.py.

What is mirrored, and how (demcal's side in brackets):
- Materials: E = 2 G (1 + nu) x stiffness_scale, nu, density [files + ApplyFidelity]; sizes x
  size_scale [ApplyFidelity]. A uniform sieve cut [d_min, d_max] (uniform in diameter by number)
  becomes DISCRETE_SIZES equally spaced diameters with equal numbers (LIGGGHTS' discrete
  distribution takes mass fractions, so each is weighted by d^3).
- Contact: Hertz normal with the restitution dashpot and Mindlin tangential with history, friction
  capped by Coulomb: LIGGGHTS `gran model hertz tangential history` is the law demcal implements
  (core/contact/hertz_mindlin.h). Rolling: `cdt`/`epsd2` or none; cohesion: `sjkr`.
- Time step: DT_FRACTION (0.25, quick fidelity's Rayleigh fraction) of the Rayleigh time of the
  smallest sphere [core/simulation/simulation.cc].
- Heap: the slot box [0, W] x [0, D] x [0, top] with six plane walls, a glued base layer (one
  sphere per pitch d_mean, lifted by up to r/2, not integrated) [objectives/common/glued_base.cc],
  the feed poured at its mass rate from a box of height max(6 d_max, 0.01 m) at pour_height, moving
  down at the entry speed demcal computes [objectives/common/feed.cc], batches every T_max; the
  run stops when the specific kinetic energy (translational + rotational, per kg of moving grains)
  falls below the criterion, checked every 0.01 s from feed end + 0.05 s, or at max_time_s
  [objectives/common/settled_run.h; demcal's second, surface criterion is not mirrored].
- Funnel: cone frustum + cylinder as an STL mesh (LIGGGHTS 3.8 has no cone primitive), a gate plane
  at z = 0 that is removed when the fill has settled (demcal moves it down faster than the grains
  fall: the same free outflow), a catch box catch_depth below. Outflow = mass of the atoms below
  z = 0, printed every sample interval; the loop stops at 99 % out, after stall_s without outflow,
  or after max_discharge_s [experiments/discharge/discharge_run.cc]. The fill is poured like the
  heap's feed, from a cylinder of 0.6 x the top diameter above the rim
  [experiments/discharge/hopper_fill.cc].
- Elongated grains: LIGGGHTS multisphere templates with demcal's 3-sphere chain (clump_members).
"""
import math

DT_FRACTION = 0.25
DISCRETE_SIZES = 5
GRAVITY = 9.81
CHECK_S = 0.01


def primes_from(start, count):
    """LIGGGHTS wants prime seeds > 10000: `count` primes from `start` up."""
    out, n = [], max(start, 10007)
    while len(out) < count:
        if all(n % k for k in range(2, int(n ** 0.5) + 1)):
            out.append(n)
        n += 1
    return out


class Model:
    """The physics of one case, in SI units at simulation (quick-fidelity) scale."""

    def __init__(self, exp, size_scale, stiffness_scale):
        mats = {m["name"]: m for m in exp["materials"]}
        self.bp, self.wall = mats["BP"], mats[exp[exp["experiment"]]["wall_material"]]

        def youngs(m):
            return 2 * m["shear_modulus_Pa"] * (1 + m["poisson_ratio"]) * stiffness_scale
        self.E_bp, self.E_wall = youngs(self.bp), youngs(self.wall)
        self.nu_bp, self.nu_wall = self.bp["poisson_ratio"], self.wall["poisson_ratio"]
        self.rho = self.bp["density_kg_m3"]
        sp = next(s for s in exp["species"] if s["name"] == "BP")
        self.d_range = [size_scale * d for d in sp["diameter_range_m"]]
        self.base_d = size_scale * 0.5 * sum(sp["diameter_range_m"])  # glued base: the feed's cut
        dflt = exp["interactions"]["default"]
        pair = next(p for p in exp["interactions"]["pairs"] if set(p["materials"]) == {"BP", "perspex"})
        self.mu_pp, self.e_pp = dflt["sliding_friction"], dflt["restitution"]
        self.mu_pw, self.e_pw = pair["sliding_friction"], pair["restitution"]
        self.mur_pp, self.mur_pw = dflt.get("rolling_friction", 0), pair.get("rolling_friction", 0)
        self.rolling = "cdt"          # None, "cdt" or "epsd2"
        self.ced_J_m3 = 0.0           # sjkr cohesion energy density, particle-particle
        self.clump = None             # aspect ratio of the 3-sphere chain; None: spheres

    def diameters(self):
        lo, hi = self.d_range
        if hi <= lo:
            return [lo], [1.0]
        ds = [lo + (hi - lo) * (k + 0.5) / DISCRETE_SIZES for k in range(DISCRETE_SIZES)]
        w = [d ** 3 for d in ds]
        return ds, [x / sum(w) for x in w]

    def timestep(self):
        r = 0.5 * min(self.d_range[0], self.base_d)
        g = self.E_bp / (2 * (1 + self.nu_bp))
        t_r = math.pi * r * math.sqrt(self.rho / g) / (0.1631 * self.nu_bp + 0.8766)
        # A clump's member spheres are smaller than its equivalent sphere.
        return DT_FRACTION * t_r * (self.clump_member_fraction() if self.clump else 1.0)

    def clump_members(self, d_eq):
        """demcal's 3-sphere chain of the equal-volume prolate spheroid of aspect ratio A
        (core/bodies/clump_shapes.cc, ApproximateEllipsoid, n = 3): end spheres at +-X with
        radius a - X touching the tips, the middle sphere at 0 with radius rho (the spheroid's
        width), X from the exact union volume = the spheroid's volume (bisection here)."""
        a = 0.5 * d_eq * self.clump ** (2 / 3)
        rho = a / self.clump
        target = 4 / 3 * math.pi * a * rho * rho
        lo, hi = a - rho, a * (1 - 1e-9)
        for _ in range(60):  # the union grows as X moves the end spheres out... then shrinks them
            x = 0.5 * (lo + hi)
            if _union_volume([(-x, a - x), (0.0, rho), (x, a - x)]) > target:
                lo = x
            else:
                hi = x
        x = 0.5 * (lo + hi)
        return [(-x, 0.0, 0.0, a - x), (0.0, 0.0, 0.0, rho), (x, 0.0, 0.0, a - x)]

    def clump_member_fraction(self):
        """Smallest member radius over the equivalent radius (sets the time step)."""
        return min(s[3] for s in self.clump_members(1.0)) / 0.5


def _union_volume(spheres, steps=4000):
    """Volume of the union of spheres (centre on x, radius) by the midpoint rule over x."""
    x0 = min(c - r for c, r in spheres)
    x1 = max(c + r for c, r in spheres)
    h = (x1 - x0) / steps
    total = 0.0
    for k in range(steps):
        x = x0 + (k + 0.5) * h
        r2 = max((r * r - (x - c) ** 2 for c, r in spheres), default=0.0)
        total += math.pi * max(r2, 0.0) * h
    return total


def _materials(m, types):
    """property/global lines for `types` atom types: the last is the wall, the rest BP."""
    n = types
    E = " ".join([f"{m.E_bp:.6g}"] * (n - 1) + [f"{m.E_wall:.6g}"])
    nu = " ".join([f"{m.nu_bp:g}"] * (n - 1) + [f"{m.nu_wall:g}"])

    def matrix(pp, pw, ww):
        rows = []
        for i in range(n):
            for j in range(n):
                wi, wj = i == n - 1, j == n - 1
                rows.append(ww if wi and wj else pw if wi or wj else pp)
        return " ".join(f"{v:.6g}" for v in rows)
    lines = [f"fix m1 all property/global youngsModulus peratomtype {E}",
             f"fix m2 all property/global poissonsRatio peratomtype {nu}",
             f"fix m3 all property/global coefficientRestitution peratomtypepair {n} "
             + matrix(m.e_pp, m.e_pw, m.e_pw),
             f"fix m4 all property/global coefficientFriction peratomtypepair {n} "
             + matrix(m.mu_pp, m.mu_pw, m.mu_pw)]
    if m.rolling:
        lines.append(f"fix m5 all property/global coefficientRollingFriction peratomtypepair {n} "
                     + matrix(m.mur_pp, m.mur_pw, m.mur_pw))
    if m.ced_J_m3 > 0:  # adhesion between grains only, not with the walls (demcal's BP-BP Gamma)
        lines.append(f"fix m6 all property/global cohesionEnergyDensity peratomtypepair {n} "
                     + matrix(m.ced_J_m3, 0.0, 0.0))
    return lines


def _law(m, walls=False):
    law = "model hertz tangential history"  # LIGGGHTS wants cohesion before rolling_friction
    if m.ced_J_m3 > 0 and not walls:
        law += " cohesion sjkr"
    if m.rolling:
        law += f" rolling_friction {m.rolling}"
    return law


def _feed_templates(m, seeds, feed_type=1):
    """Particle templates and the distribution pdd1: all BP. (The heap file's feed holds 1 %
    'BP_base', BP spheres of the base cut in all but name; not mirrored: where a case changes
    BP's shape or sizes they are the only difference, 1 % of the mass.)"""
    ds, fractions = m.diameters()
    lines, parts = [], []
    for k, (d, f) in enumerate(zip(ds, fractions)):
        tag = f"pts{k + 1}"
        if m.clump:
            spheres = " ".join(f"{x:.6g} {y:.6g} {z:.6g} {r:.6g}" for x, y, z, r in m.clump_members(d))
            lines.append(f"fix {tag} all particletemplate/multisphere {seeds[k]} atom_type {feed_type} "
                         f"density constant {m.rho:g} nspheres 3 ntry 100000 spheres {spheres} type {k + 1}")
        else:
            lines.append(f"fix {tag} all particletemplate/sphere {seeds[k]} atom_type {feed_type} "
                         f"density constant {m.rho:g} radius constant {0.5 * d:.6g}")
        parts.append(f"{tag} {f:.6g}")
    lines.append(f"fix pdd1 all particledistribution/discrete {seeds[-1]} {len(parts)} " + " ".join(parts))
    return lines


def _header(lo, hi, m, types, skin):
    return ["units si", "atom_style granular", "soft_particles yes", "atom_modify map array", "boundary f f f",
            "newton off", "communicate single vel yes", "processors * * 1",
            f"region domain block {lo[0]:.6g} {hi[0]:.6g} {lo[1]:.6g} {hi[1]:.6g} {lo[2]:.6g} {hi[2]:.6g} units box",
            f"create_box {types} domain", f"neighbor {skin:.6g} bin", "neigh_modify delay 0",
            *_materials(m, types), f"pair_style gran {_law(m)}", "pair_coeff * *",
            f"timestep {m.timestep():.6g}", f"fix gravi all gravity {GRAVITY} vector 0.0 0.0 -1.0",
            "group nve_group region domain"]


def _integration(m):
    if m.clump:
        return ["fix ms all multisphere", "compute rke all erotate/multisphere",
                "compute tke all ke/multisphere", "variable ke equal c_tke+c_rke"]
    return ["fix integr nve_group nve/sphere", "compute rke nve_group erotate/sphere",
            "compute tke nve_group ke", "variable ke equal c_tke+c_rke"]


def _settle_loop(name, start_steps, dt, crit, max_s, moving_kg):
    """Runs `start_steps`, then CHECK_S chunks until KE per kg of the moving grains < crit. The
    moving mass is the feed's (all of it is in by then; LIGGGHTS refuses group functions such as
    mass(group) beside fix multisphere)."""
    chunk = max(1, round(CHECK_S / dt))
    return [f"run {start_steps}",
            f"label {name}",
            f"variable ske_{name} equal v_ke/{moving_kg:.9g}",
            f"if \"${{ske_{name}}} < {crit:g}\" then \"jump SELF {name}_done\"",
            f"if \"$(step*{dt:.9g}) > {max_s:g}\" then \"print 'DEMCAL_STATUS not_settled'\" \"jump SELF {name}_done\"",
            f"run {chunk}",
            f"jump SELF {name}",
            f"label {name}_done",
            f"print 'DEMCAL_SETTLED $(step*{dt:.9g}) ${{ske_{name}}}'"]


def entry_speed(m, region_vol, h, rate, solid_fraction=0.2):
    t_max = solid_fraction * region_vol / (rate / m.rho)
    v = 0.0 if math.sqrt(2 * h / GRAVITY) <= t_max else h / t_max - 0.5 * GRAVITY * t_max
    return v, t_max


def heap_deck(m, aor, seeds, rng, dump_path):
    """The slot heap of an `aor` section; `rng` lifts the base spheres (a random.Random)."""
    W, D, ph = aor["width_m"], aor["depth_m"], aor["pour_height_m"]
    dmax = m.d_range[1]
    fh = max(6 * dmax, 0.01)
    top = ph + fh + 0.02
    dt = m.timestep()
    x0 = 0.5 * (W - aor["feed_width_m"])
    feed = aor["feed"]
    v, t_max = entry_speed(m, aor["feed_width_m"] * D * fh, fh, feed["mass_rate_kg_s"])
    lines = _header((-0.02, -0.02, -0.02), (W + 0.02, D + 0.02, top + 0.02), m, 3, 0.25 * dmax)
    walls = [("x0", "xplane 0"), ("x1", f"xplane {W:.6g}"), ("y0", "yplane 0"),
             ("y1", f"yplane {D:.6g}"), ("z0", "zplane 0"), ("z1", f"zplane {top:.6g}")]
    lines += [f"fix w{k} all wall/gran {_law(m, True)} primitive type 3 {p}" for k, p in walls]
    d = m.base_d
    nx, ny = int(W // d), int(D // d)
    cx, cy = 0.5 * W - 0.5 * (nx - 1) * d, 0.5 * D - 0.5 * (ny - 1) * d
    for i in range(nx):
        for j in range(ny):
            z = 0.5 * d * (1 + 0.5 * rng.random())
            lines.append(f"create_atoms 2 single {cx + i * d:.7g} {cy + j * d:.7g} {z:.7g} units box")
    lines += [f"set type 2 diameter {d:.7g}", f"set type 2 density {m.rho:g}"]
    lines += _feed_templates(m, seeds[1:])
    every = max(1, round(t_max / dt))
    lines += [f"region feed block {x0:.6g} {x0 + aor['feed_width_m']:.6g} 0 {D:.6g} {ph:.6g} {ph + fh:.6g} units box",
              f"fix ins nve_group insert/rate/region seed {seeds[0]} distributiontemplate pdd1 "
              f"mass {feed['mass_kg']:g} massrate {feed['mass_rate_kg_s']:g} insert_every {every} "
              f"overlapcheck yes all_in yes vel constant 0 0 {-v:.6g} region feed ntry_mc 10000"]
    lines += _integration(m)
    lines += ["thermo_style custom step atoms c_tke c_rke cpu", f"thermo {max(1, round(0.05 / dt))}",
              "thermo_modify lost ignore norm no"]
    settle = aor["settle"]
    start = round((feed["mass_kg"] / feed["mass_rate_kg_s"] + 0.05) / dt)
    lines += _settle_loop("heap", start, dt, settle["specific_kinetic_J_kg"], settle["max_time_s"],
                          feed["mass_kg"])
    lines += [f"dump fin all custom 1 {dump_path} id type x y z radius", "run 0", "undump fin"]
    return "\n".join(lines) + "\n"


def hopper_stl(path, h, segments=48):
    """ASCII STL of the cone frustum (orifice at z = 0) and the cylinder above it."""
    r0, r1 = 0.5 * h["orifice_diameter_m"], 0.5 * h["top_diameter_m"]
    zc = (r1 - r0) / math.tan(math.radians(h["cone_half_angle_deg"]))
    zt = zc + h["cylinder_height_m"]
    rings = [(r0, 0.0), (r1, zc)] + ([(r1, zt)] if zt > zc else [])
    out = ["solid hopper"]
    for (ra, za), (rb, zb) in zip(rings, rings[1:]):
        for k in range(segments):
            a0, a1 = 2 * math.pi * k / segments, 2 * math.pi * (k + 1) / segments
            p = [(ra * math.cos(a0), ra * math.sin(a0), za), (ra * math.cos(a1), ra * math.sin(a1), za),
                 (rb * math.cos(a1), rb * math.sin(a1), zb), (rb * math.cos(a0), rb * math.sin(a0), zb)]
            for tri in ((p[0], p[1], p[2]), (p[0], p[2], p[3])):
                out.append("facet normal 0 0 0\nouter loop")
                out += [f"vertex {x:.8g} {y:.8g} {z:.8g}" for x, y, z in tri]
                out.append("endloop\nendfacet")
    out.append("endsolid hopper")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return zc, zt


def funnel_deck(m, dis, seeds, stl_path, outflow_path, dump_path):
    h = dis["hopper"]
    r1 = 0.5 * h["top_diameter_m"]
    zc, zt = hopper_stl(stl_path, h)
    dmax = m.d_range[1]
    half, catch = 0.75 * h["top_diameter_m"], dis["catch_depth_m"]
    fz0, fh = zt + dmax, max(6 * dmax, 0.01)
    top = fz0 + fh
    dt = m.timestep()
    feed = dis["feed"]
    rf = 0.6 * r1
    v, t_max = entry_speed(m, math.pi * rf * rf * fh, fh, feed["mass_rate_kg_s"])
    lines = _header((-half - 0.02, -half - 0.02, -catch - 0.02), (half + 0.02, half + 0.02, top + 0.02),
                    m, 2, 0.25 * dmax)
    lines += [f"fix hopper all mesh/surface file {stl_path} type 2 curvature 1e-5",
              f"fix whopper all wall/gran {_law(m, True)} mesh n_meshes 1 meshes hopper",
              f"fix wgate all wall/gran {_law(m, True)} primitive type 2 zplane 0",
              f"fix wfloor all wall/gran {_law(m, True)} primitive type 2 zplane {-catch:.6g}",
              *[f"fix wc{k} all wall/gran {_law(m, True)} primitive type 2 {a}plane {sgn * half:.6g}"
                for k, (a, sgn) in enumerate((("x", -1), ("x", 1), ("y", -1), ("y", 1)))],
              *_feed_templates(m, seeds[1:]),
              f"region feed cylinder z 0 0 {rf:.6g} {fz0:.6g} {top:.6g} units box",
              f"fix ins nve_group insert/rate/region seed {seeds[0]} distributiontemplate pdd1 "
              f"mass {feed['mass_kg']:g} massrate {feed['mass_rate_kg_s']:g} insert_every {max(1, round(t_max / dt))} "
              f"overlapcheck yes all_in yes vel constant 0 0 {-v:.6g} region feed ntry_mc 10000",
              *_integration(m),
              # Outflow = mass of the atoms below the orifice plane, by per-atom variables (group
              # functions are refused beside fix multisphere); in the thermo line so that the
              # computes are current between runs.
              "variable below atom z<0", "variable mb atom mass*v_below", "variable ma atom mass",
              "compute cout all reduce sum v_mb", "compute call all reduce sum v_ma",
              "thermo_style custom step atoms c_tke c_rke c_cout c_call cpu",
              f"thermo {max(1, round(0.05 / dt))}", "thermo_modify lost ignore norm no"]
    settle = dis["settle"]
    start = round((feed["mass_kg"] / feed["mass_rate_kg_s"] + 0.05) / dt)
    lines += _settle_loop("fill", start, dt, settle["specific_kinetic_J_kg"], settle["max_time_s"],
                          feed["mass_kg"])
    # Bulk density probe and the outflow record need positions: one dump at the gate opening.
    lines += [f"dump fill all custom 1 {dump_path} id type x y z radius mass", "run 0", "undump fill",
              "unfix wgate",
              "variable tnow equal step*%.9g" % dt,
              "variable mout equal c_cout",
              "variable fillm equal $(c_call)",
              "variable done equal v_mout>=0.99*v_fillm",
              f"fix rec all print {max(1, round(dis['sample_interval_s'] / dt))} \"${{tnow}} ${{mout}}\" "
              f"file {outflow_path} screen no title \"t_s mass_below_kg\""]
    chunk = max(1, round(dis["sample_interval_s"] / dt))
    stall_chunks = max(1, round(dis["stall_s"] / dis["sample_interval_s"]))
    max_chunks = round(dis["max_discharge_s"] / dis["sample_interval_s"])
    lines += ["variable last equal 0", "variable idle equal 0", "variable k loop %d" % max_chunks,
              "label discharge", f"run {chunk}",
              "if \"${done} > 0\" then \"print 'DEMCAL_STATUS done'\" \"jump SELF out\"",
              "if \"${mout} > ${last}\" then \"variable idle equal 0\" else \"variable idle equal $(v_idle+1)\"",
              "variable last equal ${mout}",
              f"if \"${{idle}} >= {stall_chunks}\" then \"print 'DEMCAL_STATUS jammed'\" \"jump SELF out\"",
              "next k", "jump SELF discharge", "print 'DEMCAL_STATUS not_empty'", "label out",
              # fix print writes on multiples of its interval, which need not end a chunk: one more
              # chunk puts the state at the stop (or later) into the record.
              f"run {chunk}"]
    return "\n".join(lines) + "\n"
