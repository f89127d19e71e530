#pragma once
// Normal slot "sjkr": Hertz–Mindlin plus LIGGGHTS-PUBLIC 3.8's `cohesion sjkr` (docs/physics.md
// §3.5). While two spheres overlap, an attractive force k·A acts along the normal, k the pair's
// cohesion energy density (J/m³) and A = π a² the area of the circle where the two sphere
// surfaces intersect (LIGGGHTS-PUBLIC src/cohesion_model_sjkr.h). For spheres of radii R_i, R_j
// whose centres are r = R_i + R_j − δ apart (Weisstein, "Sphere-Sphere Intersection", MathWorld,
// Eq. 8, written in factors so that small overlaps lose no digits):
//   a² = δ (2R_i − δ)(2R_j − δ)(2R_i + 2R_j − δ) / (4 r²);
// against a wall, the sphere's cap circle at distance R_i − δ from its centre: a² = δ (2R_i − δ).
// What LIGGGHTS does with the force, and so this law (each read in its source):
//  * the Coulomb limit multiplies |F_n| without the cohesion (`tangential_reduce` is off by
//    default, so sidata.Fn stays the Hertz force with its damping: tangential_model_history.h);
//  * the rolling torque of `rolling_friction cdt` multiplies k_n·δ_n, Hertz's elastic force alone
//    (rolling_model_cdt.h); so friction_load_N and rolling_load_N are Hertz–Mindlin's;
//  * cohesion acts wherever the pair's k > 0, walls included (fix wall/gran runs the same
//    cohesion model, with area_ratio = 1 for a wall);
//  * the force ends when the spheres separate: surfacesIntersect is called only while they
//    overlap, so there is no neck, no hysteresis and no pull-off distance (kAdhesive = false).
// With k = 0 the force is exactly Hertz–Mindlin's (the same function, nothing subtracted).
#include <cmath>
#include <numbers>

#include "core/contact/contact_state.h"
#include "core/contact/hertz_mindlin.h"
#include "core/contact/rolling_model.h"

namespace demcal::core {

struct SjkrNormal {
  static constexpr const char* kName = "sjkr";
  // A contact ends at touching, as Hertz–Mindlin's: the cohesion acts only while overlapping.
  static constexpr bool kAdhesive = false;

  // Called for by a pair with cohesion energy density k > 0.
  static bool CalledFor(const PairParameters& p) { return p.cohesion_energy_density_J_m3 > 0; }
  // Options of the scene's contact_model section: none (LIGGGHTS' tangential_reduce is off).
  static bool Make(const RollingModelSpec&, SjkrNormal* law) {
    *law = {};
    return true;
  }
  // Pair constants derived once at setup: none (k is read as given).
  static void Resolve(ResolvedPair&) {}
  static double BreakGap(double, const ResolvedPair&) { return 0; }
  static bool Holds(double, double, const ResolvedPair&) { return false; }

  // Upper bound of the energy `contacts` contacts of a sphere of radius r can release by
  // attraction: the depth of one contact's potential well, the cohesion's work k π ∫ a² dδ less
  // Hertz's elastic energy, is largest at δ_eq where the two forces balance. With a² ≤ 2R*δ
  // (equality as δ → 0) and R* ≤ r: 2πkrδ_eq = (4/3)E*√r δ_eq^{3/2} gives
  // δ_eq = r (3πk / (2E*))², and the depth is below πkr δ_eq².
  static double AttractionEnergyBound(double r, const ResolvedPair& p, int contacts) {
    const double k = p.cohesion_energy_density_J_m3;
    if (k <= 0) return 0;
    const double ratio = 3 * std::numbers::pi * k / (2 * p.effective_youngs_Pa);
    const double delta_eq = r * ratio * ratio;
    return contacts * std::numbers::pi * k * r * delta_eq * delta_eq;
  }

  // Squared radius of the circle where the surfaces intersect (see the top), m².
  DEMCAL_HOT_INLINE static double IntersectionRadius2(const ContactGeometry& g) {
    const double d = g.overlap_m, ri = g.radius_i_m, rj = g.radius_j_m;
    if (rj == 0) return d * (2 * ri - d);  // a wall: the sphere's cap
    const double r = ri + rj - d;
    return d * (2 * ri - d) * (2 * rj - d) * (2 * (ri + rj) - d) / (4 * r * r);
  }

  DEMCAL_HOT_INLINE NormalForce Force(const ContactGeometry& g, const ResolvedPair& p,
                                      ContactHistory& h) const {
    return Compute(g, p, h);
  }

  DEMCAL_HOT_INLINE static NormalForce Compute(const ContactGeometry& g, const ResolvedPair& p,
                                               ContactHistory& h) {
    NormalForce n = HertzMindlinNormal::Compute(g, p, h);
    const double k = p.cohesion_energy_density_J_m3;
    if (k <= 0) return n;
    const double cohesion = k * std::numbers::pi * IntersectionRadius2(g);
    n.elastic_N -= cohesion;
    n.total_N -= cohesion;
    return n;  // friction_load_N, rolling_load_N: Hertz–Mindlin's, as LIGGGHTS (see the top)
  }
};

}  // namespace demcal::core
