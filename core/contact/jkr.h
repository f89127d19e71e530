#pragma once
// Normal slot "jkr": Hertz–Mindlin with JKR adhesion, EDEM convention (physics.md §3 and the
// demcal decision at its top). Γ is EDEM's interfacial energy; the work of adhesion is w = 2Γ:
//   F(a) = 4E*a³/(3R*) − 4 sqrt(π Γ E*) a^{3/2},   δ(a) = a²/R* − sqrt(4π Γ a / E*).
// The contact forms when the spheres touch (δ = 0, where F = −8/9 F_c, F_c = 3πΓR*) and breaks
// when they are pulled apart to the displacement-controlled snap-off δ_min =
// −(3/4)(π² w² R*/E*²)^{1/3} (hysteresis). Choices (documented in the README):
//  * contact radius from δ: Parteli et al. (2014) closed form of the quartic, stable branch,
//    polished by one Newton step;
//  * normal damping as Hertz–Mindlin with S_n = 2 E* a (equal to HM's when a² = R* δ);
//  * Coulomb and rolling limits use the repulsive (Hertz) part 4E*a³/(3R*) of the force
//    (EDEM: friction "depends on the positive repulsive part of the JKR normal force").
// With Γ = 0 it is exactly Hertz–Mindlin (the same function is called).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/contact/contact_state.h"
#include "core/contact/hertz_mindlin.h"

namespace demcal::core {

struct JkrNormal {
  static constexpr bool kAdhesive = true;

  // |δ_min|: the largest separation (as a positive gap) an existing contact survives.
  static double BreakGap(double r_eff, double e_star, double gamma) {
    const double w = 2.0 * gamma;
    return 0.75 * std::cbrt(std::numbers::pi * std::numbers::pi * w * w * r_eff / (e_star * e_star));
  }

  // Contact radius on the stable branch for overlap δ >= δ_min (Parteli et al. 2014).
  static double ContactRadius(double delta, double r_eff, double e_star, double gamma) {
    const double w = 2.0 * gamma;
    const double c0 = r_eff * r_eff * delta * delta;
    const double c1 = -2.0 * std::numbers::pi * w * r_eff * r_eff / e_star;
    const double c2 = -2.0 * r_eff * delta;
    const double p = -c2 * c2 / 12.0 - c0;
    const double q = -c2 * c2 * c2 / 108.0 + c0 * c2 / 3.0 - c1 * c1 / 8.0;
    const double u = std::cbrt(-0.5 * q + std::sqrt(std::max(0.0, 0.25 * q * q + p * p * p / 27.0)));
    const double s = u != 0.0 ? -5.0 * c2 / 6.0 + u - p / (3.0 * u) : -5.0 * c2 / 6.0 - std::cbrt(q);
    const double omega = std::sqrt(std::max(0.0, c2 + 2.0 * s));
    const double lambda = omega > 0 ? c1 / (2.0 * omega) : 0.0;
    double a = 0.5 * (omega + std::sqrt(std::max(0.0, omega * omega - 4.0 * (c2 + s + lambda))));
    // One Newton step on δ(a) − δ = 0 removes the round-off of the closed form.
    const double k = std::sqrt(4.0 * std::numbers::pi * gamma / e_star);
    if (a > 0) {
      const double f = a * a / r_eff - k * std::sqrt(a) - delta;
      const double df = 2.0 * a / r_eff - 0.5 * k / std::sqrt(a);
      if (df > 0) a -= f / df;
    }
    return a;
  }

  DEMCAL_HOT_INLINE static NormalForce Compute(const ContactGeometry& g, const ResolvedPair& p) {
    const double gamma = p.interfacial_energy_J_m2;
    if (gamma <= 0) return HertzMindlinNormal::Compute(g, p);
    constexpr double kTwoSqrtFiveSixths = 1.8257418583505538;
    const double e_star = p.effective_youngs_Pa, r_eff = g.effective_radius_m;
    const double a = ContactRadius(g.overlap_m, r_eff, e_star, gamma);
    const double hertz = 4.0 * e_star * a * a * a / (3.0 * r_eff);
    const double adhesion = 4.0 * std::sqrt(std::numbers::pi * gamma * e_star) * a * std::sqrt(a);
    const double s_n = 2.0 * e_star * a;
    const double c_n = -kTwoSqrtFiveSixths * p.beta * std::sqrt(s_n * g.effective_mass_kg);
    const double v_n = Dot(g.relative_velocity_m_s, g.normal);
    NormalForce n;
    n.elastic_N = hertz - adhesion;
    n.total_N = n.elastic_N - c_n * v_n;
    n.stiffness_n = s_n;
    n.secant_kn = (4.0 / 3.0) * e_star * a;
    n.contact_radius_m = a;
    n.friction_load_N = hertz;
    n.rolling_load_N = hertz;
    return n;
  }
};

}  // namespace demcal::core
