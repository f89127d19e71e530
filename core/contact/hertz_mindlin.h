#pragma once
// Hertz normal force with the EDEM/LIGGGHTS restitution dashpot (docs/physics.md §1.2):
//   F_n = (4/3) E* sqrt(R*) δ^{3/2} − 2 sqrt(5/6) β sqrt(S_n m*) v_n,  S_n = 2 E* sqrt(R* δ).
// The force is not clamped at zero: the contact ends at δ = 0, which makes the restitution
// mapping e ↔ β exact and velocity independent (docs/physics.md §1.4 table, first column).
#include <cmath>

#include "core/contact/contact_state.h"

namespace demcal::core {

struct HertzMindlinNormal {
  static constexpr bool kAdhesive = false;
  static double BreakGap(double, double, double) { return 0; }
  static bool Holds(double, double, double, double) { return false; }

  DEMCAL_HOT_INLINE static NormalForce Compute(const ContactGeometry& g, const ResolvedPair& p,
                                               ContactHistory&) {
    constexpr double kTwoSqrtFiveSixths = 1.8257418583505538;  // 2 sqrt(5/6)
    const double a = std::sqrt(g.effective_radius_m * g.overlap_m);
    const double e_star = p.effective_youngs_Pa;
    const double secant = (4.0 / 3.0) * e_star * a;
    const double s_n = 2.0 * e_star * a;
    const double c_n = -kTwoSqrtFiveSixths * p.beta * std::sqrt(s_n * g.effective_mass_kg);
    const double v_n = Dot(g.relative_velocity_m_s, g.normal);  // < 0 while approaching
    const double elastic = secant * g.overlap_m;
    const double total = elastic - c_n * v_n;
    // LIGGGHTS caps friction with |F_n| (damping included) and rolling with the elastic part.
    return {elastic, total, s_n, secant, a, std::abs(total), elastic, c_n};
  }
};

}  // namespace demcal::core
