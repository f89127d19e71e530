"""demcal's observables measured on LIGGGHTS output, ported line for line from demcal (demcal has
no command that measures a particle dump). Used by scripts/make_liggghts_datasets.py; checked
against demcal's own numbers on demcal's VTK heaps by `--check-port BUILD_DIR`.

Heap (objectives/metrics/repose_angle.cc, surface_profile.cc, flank_fit.cc, line_fit.cc,
heap_crest.cc; the `fit` method, window 0.1-0.9 of H, cell 1.5 x mean sphere diameter, >= 5
points per flank): the surface profile is the highest sphere top per x cell; the apex is the
highest of the 3-cell running mean's best cell and its neighbours; each flank (left and right of
the apex) is fitted by least squares inside the height window; angle = mean over flanks of
atan(-slope); heap_height_m = max top - base top (1.125 d_base above the floor);
crest_drop_m = mean fitted intercept at the apex - (base + H).
Funnel (objectives/metrics/discharge_metrics.cc, experiments/discharge/hopper_fill.cc):
discharge_time_s = gate opening -> 99 % of the fill out (linear interpolation between samples);
mass_flow_kg_s = least-squares slope of mass out against time between 20 % and 80 % of the fill;
bulk_density_kg_m3 = mass of the grain centres in the probe (2 d_max above the orifice up to the
median grain height, radius = hopper radius - d_max) over its volume, at the gate opening.
"""
import math


def read_dump(path):
    """LAMMPS/LIGGGHTS custom dump (last frame): list of dicts keyed by the column names."""
    rows, cols, reading = [], [], False
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM: ATOMS"):
                cols, rows, reading = line.split()[2:], [], True
            elif line.startswith("ITEM:"):
                reading = False
            elif reading and line.strip():
                rows.append(dict(zip(cols, map(float, line.split()))))
    return rows


def _fit_line(xs, ys):
    n = len(xs)
    if n < 2:
        return None
    xm, ym = sum(xs) / n, sum(ys) / n
    sxx = sum((x - xm) ** 2 for x in xs)
    sxy = sum((x - xm) * (y - ym) for x, y in zip(xs, ys))
    if not sxx > 0:
        return None
    slope = sxy / sxx
    return slope, ym - slope * xm


def _apex_index(profile):
    n = len(profile)
    best, best_mean = 0, -math.inf
    for i in range(n):
        lo, hi = max(0, i - 1), min(n - 1, i + 1)
        mean = sum(profile[j][1] for j in range(lo, hi + 1)) / (hi - lo + 1)
        if mean > best_mean:
            best_mean, best = mean, i
    out = best
    for j in range(max(0, best - 1), min(n - 1, best + 1) + 1):
        if profile[j][1] > profile[out][1]:
            out = j
    return out


def slot_heap(spheres, base_z_m, window=(0.1, 0.9), min_points=5):
    """spheres: (x, z, r) of the heap's grains (glued base excluded). Returns a dict with ok,
    angle_deg, heap_height_m, crest_drop_m, flanks."""
    if not spheres:
        return {"ok": False, "message": "no spheres"}
    cell = 1.5 * sum(2 * r for _, _, r in spheres) / len(spheres)
    top = max(z + r for _, z, r in spheres)
    H = top - base_z_m
    if not H > 0:
        return {"ok": False, "message": "no heap"}
    x_min = min(x for x, _, _ in spheres)
    cells = {}
    for x, z, r in spheres:
        k = math.floor((x - x_min) / cell)
        if k not in cells or z + r > cells[k][1]:
            cells[k] = (x, z + r)
    profile = sorted(cells.values())
    apex = _apex_index(profile)
    s0 = profile[apex][0]
    left = [(s0 - profile[i][0], profile[i][1]) for i in range(apex, -1, -1)]
    right = [(profile[i][0] - s0, profile[i][1]) for i in range(apex, len(profile))]
    flanks = []
    for outward in (left, right):
        pts = [(s, t) for s, t in outward if window[0] <= (t - base_z_m) / H <= window[1]]
        if len(pts) < min_points:
            continue
        fit = _fit_line([p[0] for p in pts], [p[1] for p in pts])
        if fit is None or not fit[0] < 0:
            continue
        flanks.append({"angle_deg": math.degrees(math.atan(-fit[0])), "intercept_m": fit[1],
                       "points": len(pts)})
    if not flanks:
        return {"ok": False, "message": "no flank could be fitted", "heap_height_m": H}
    angle = sum(f["angle_deg"] for f in flanks) / len(flanks)
    apex_z = sum(f["intercept_m"] for f in flanks) / len(flanks)
    return {"ok": True, "angle_deg": angle, "heap_height_m": H,
            "crest_drop_m": apex_z - (base_z_m + H), "flanks": flanks}


def discharge(samples, fill_kg, fraction=0.99, window=(0.2, 0.8)):
    """samples: (t since gate opening, mass out) in time order, starting at the opening."""
    if len(samples) < 2 or not fill_kg > 0:
        return {"ok": False, "message": "no outflow record"}
    end = fraction * fill_kg
    if samples[-1][1] < end:
        return {"ok": False, "message": f"discharge incomplete: {samples[-1][1]:.4g} of {fill_kg:.4g} kg"}
    t_prev, m_prev, t_end = 0.0, 0.0, samples[-1][0]
    for t, m in samples:
        if t <= 0:
            continue
        if m >= end:
            t_end = t_prev + (end - m_prev) / (m - m_prev) * (t - t_prev)
            break
        t_prev, m_prev = t, m
    pts = [(t, m) for t, m in samples if t >= 0 and window[0] * fill_kg <= m <= window[1] * fill_kg]
    fit = _fit_line([p[0] for p in pts], [p[1] for p in pts]) if len(pts) >= 3 else None
    if fit is None:
        return {"ok": False, "message": f"{len(pts)} samples inside the flow window (need 3)"}
    return {"ok": True, "discharge_time_s": t_end, "mass_flow_kg_s": fit[0]}


def hopper_radius(h, z):
    r0, r1 = 0.5 * h["orifice_diameter_m"], 0.5 * h["top_diameter_m"]
    zc = (r1 - r0) / math.tan(math.radians(h["cone_half_angle_deg"]))
    return r1 if z >= zc else r0 + (r1 - r0) * z / zc


def bulk_density(grains, h, d_max):
    """grains: (x, y, z, mass) of whole grains (a clump once, at its centre of mass)."""
    r0, r1 = 0.5 * h["orifice_diameter_m"], 0.5 * h["top_diameter_m"]
    zt = (r1 - r0) / math.tan(math.radians(h["cone_half_angle_deg"])) + h["cylinder_height_m"]
    heights = sorted(z for _, _, z, _ in grains if z > 0)
    if not heights:
        return 0.0
    z_lo, z_hi = 2 * d_max, min(heights[len(heights) // 2], zt)
    if not z_hi > z_lo:
        return 0.0
    n = 200
    vol = sum(math.pi * max(0.0, hopper_radius(h, z_lo + (k + 0.5) * (z_hi - z_lo) / n) - d_max) ** 2
              * (z_hi - z_lo) / n for k in range(n))
    mass = sum(m for x, y, z, m in grains
               if z_lo <= z <= z_hi and math.hypot(x, y) <= hopper_radius(h, z) - d_max)
    return mass / vol if vol > 0 else 0.0
