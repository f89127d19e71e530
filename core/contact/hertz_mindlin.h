#pragma once
// Hertz normal force with the EDEM/LIGGGHTS restitution dashpot (docs/physics.md §1.2):
//   F_n = (4/3) E* sqrt(R*) δ^{3/2} − 2 sqrt(5/6) β sqrt(S_n m*) v_n,  S_n = 2 E* sqrt(R* δ).
// The force is not clamped at zero: the contact ends at δ = 0, which makes the restitution
// mapping e ↔ β exact and velocity independent (docs/physics.md §1.4 table, first column).
#include <cmath>

#include "core/contact/contact_state.h"
#include "core/contact/rolling_model.h"

namespace demcal::core {

// The law every normal_model.h entry offers, with what this one does for each.
struct HertzMindlinNormal {
  static constexpr const char* kName = "hertz_mindlin";
  // A contact exists while the bodies are pressed together (δ > 0), never beyond touching.
  static constexpr bool kAdhesive = false;

  // Pair properties that call for this law: none (it is the default; it reads E* and β, which
  // every pair has).
  static bool CalledFor(const PairParameters&) { return false; }
  // Options of the scene's contact_model section: none.
  static bool Make(const RollingModelSpec&, HertzMindlinNormal* law) {
    *law = {};
    return true;
  }
  // Pair constants derived once at setup: none.
  static void Resolve(ResolvedPair&) {}
  // How far beyond touching (a gap, m) an existing contact survives: not at all.
  static double BreakGap(double, const ResolvedPair&) { return 0; }
  // Whether a stretched contact (gap = −δ > 0) holds: never.
  static bool Holds(double, double, const ResolvedPair&) { return false; }
  // Upper bound of the energy `contacts` contacts of a sphere of radius r can release by
  // attraction (the blow-up check's budget): none.
  static double AttractionEnergyBound(double, const ResolvedPair&, int) { return 0; }

  // The normal force of one contact (the contact loop's entry; Compute with this law's options).
  DEMCAL_HOT_INLINE NormalForce Force(const ContactGeometry& g, const ResolvedPair& p,
                                      ContactHistory& h) const {
    return Compute(g, p, h);
  }

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
