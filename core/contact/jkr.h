#pragma once
// Normal slot "jkr": Hertz–Mindlin with JKR adhesion, EDEM convention (docs/physics.md §3 and the
// demcal decision at its top). Γ is EDEM's interfacial energy; the work of adhesion is w = 2Γ:
//   F(a) = 4E*a³/(3R*) − 4 sqrt(π Γ E*) a^{3/2},   δ(a) = a²/R* − sqrt(4π Γ a / E*).
// The contact forms when the spheres touch (δ = 0, where F = −8/9 F_c, F_c = 3πΓR*) and breaks
// when they are pulled apart to the displacement-controlled snap-off δ_min =
// −(3/4)(π² w² R*/E*²)^{1/3} (hysteresis). Choices (documented in the README):
//  * contact radius from δ: Parteli et al. (2014) closed form of the quartic, stable branch,
//    polished by one Newton step, for a new contact; afterwards Newton steps on the stable branch
//    from the previous step's radius (kept in the contact history), which costs a fraction of it;
//  * normal damping as Hertz–Mindlin with S_n = 2 E* a (equal to HM's when a² = R* δ);
//  * the Coulomb limit uses the repulsive (Hertz) part 4E*a³/(3R*) of the force (EDEM: friction
//    "depends on the positive repulsive part of the JKR normal force"); so does rolling_load_N
//    here, which Force() replaces by the transmitted load max(0, F) unless the scene asks for
//    "repulsive" (JkrRollingLoad, rolling_model.h, explains why "net" is the default).
// With Γ = 0 it is exactly Hertz–Mindlin (the same function is called).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/contact/contact_state.h"
#include "core/contact/hertz_mindlin.h"
#include "core/contact/rolling_model.h"

namespace demcal::core {

// Cube root for the contact loop: an exponent-bit estimate refined by two Halley steps, relative
// error < 1e-14 over the whole double range (std::cbrt calls into libm's frexp/scalbn and cost a
// fifth of a JKR force pass). Exact 0 for 0.
DEMCAL_HOT_INLINE double FastCbrt(double x) {
  if (x == 0) return 0;
  const double ax = std::abs(x);
  double y = std::bit_cast<double>(std::bit_cast<uint64_t>(ax) / 3 + 0x2A9F7893782DA1CEull);
  for (int step = 0; step < 2; ++step) {
    const double y3 = y * y * y;
    y *= (y3 + 2 * ax) / (2 * y3 + ax);
  }
  return x < 0 ? -y : y;
}

// The law every normal_model.h entry offers (HertzMindlinNormal lists them), with its option:
// the load its rolling limit multiplies (JkrRollingLoad, rolling_model.h, explains the choice).
struct JkrNormal {
  static constexpr const char* kName = "jkr";
  // An existing contact survives stretching up to the break gap (the neck of the hysteresis).
  static constexpr bool kAdhesive = true;

  JkrRollingLoad rolling_load = JkrRollingLoad::kNet;

  // Called for by a pair with interfacial energy Γ > 0; reads Γ and E* (pairs with Γ = 0 get
  // Hertz–Mindlin from it, exactly).
  static bool CalledFor(const PairParameters& p) { return p.interfacial_energy_J_m2 > 0; }
  // Its option from the scene's contact_model section: jkr_rolling_load (false if unknown).
  static bool Make(const RollingModelSpec& spec, JkrNormal* law) {
    JkrNormal made;
    if (!ParseJkrRollingLoad(spec.jkr_rolling_load, &made.rolling_load)) return false;
    *law = made;
    return true;
  }
  // The pair constant the force loop reads: the adhesion length k (0 without Γ).
  static void Resolve(ResolvedPair& p) {
    const double gamma = p.interfacial_energy_J_m2;
    p.jkr_adhesion_length = gamma > 0 ? AdhesionLength(p.effective_youngs_Pa, gamma) : 0.0;
  }
  // |δ_min| of the pair (0 without Γ): how far beyond touching an existing contact survives.
  DEMCAL_HOT_INLINE static double BreakGap(double r_eff, const ResolvedPair& p) {
    const double gamma = p.interfacial_energy_J_m2;
    return gamma > 0 ? BreakGap(r_eff, p.effective_youngs_Pa, gamma) : 0.0;
  }
  // Whether a stretched contact of the pair (gap = −δ > 0) holds.
  DEMCAL_HOT_INLINE static bool Holds(double gap, double r_eff, const ResolvedPair& p) {
    return p.interfacial_energy_J_m2 > 0 &&
           Holds(gap, r_eff, p.effective_youngs_Pa, p.interfacial_energy_J_m2);
  }
  // Upper bound of the energy `contacts` contacts of a sphere of radius r can release by
  // attraction: per contact at most F_c (3|δ_min|) (the attractive force never exceeds
  // F_c = 3πΓR over a travel of δ_eq − δ_min).
  static double AttractionEnergyBound(double r, const ResolvedPair& p, int contacts) {
    const double gamma = p.interfacial_energy_J_m2;
    if (gamma <= 0) return 0;
    const double f_c = 3 * std::numbers::pi * gamma * r;
    const double gap = BreakGap(r, p.effective_youngs_Pa, gamma);
    return contacts * f_c * 3 * gap;
  }

  // The normal force of one contact (the contact loop's entry): Compute, with the rolling load
  // this law was made with.
  DEMCAL_HOT_INLINE NormalForce Force(const ContactGeometry& g, const ResolvedPair& p,
                                      ContactHistory& h) const {
    NormalForce n = Compute(g, p, h);
    // Γ = 0 pairs: Hertz's elastic force, which is the rolling load already (δ > 0).
    if (rolling_load == JkrRollingLoad::kNet) n.rolling_load_N = std::max(0.0, n.elastic_N);
    return n;
  }

  // |δ_min|: the largest separation (as a positive gap) an existing contact survives.
  DEMCAL_HOT_INLINE static double BreakGap(double r_eff, double e_star, double gamma) {
    const double w = 2.0 * gamma;
    return 0.75 * FastCbrt(std::numbers::pi * std::numbers::pi * w * w * r_eff / (e_star * e_star));
  }

  // Whether a stretched contact (gap = −δ > 0) holds: gap < BreakGap, compared in cubes so the
  // force loop takes no cube root.
  DEMCAL_HOT_INLINE static bool Holds(double gap, double r_eff, double e_star, double gamma) {
    const double w = 2.0 * gamma;
    constexpr double kCube = 27.0 / 64.0 * std::numbers::pi * std::numbers::pi;  // 0.75³ π²
    return gap * gap * gap * (e_star * e_star) < kCube * w * w * r_eff;
  }

  // Adhesion length k = sqrt(4πΓ/E*) (m^½): δ(a) = a²/R* − k √a.
  static double AdhesionLength(double e_star, double gamma) {
    return std::sqrt(4.0 * std::numbers::pi * gamma / e_star);
  }

  struct Radius {
    double a = 0;       // contact radius, m
    double sqrt_a = 0;  // √a
  };

  // Contact radius on the stable branch for overlap δ >= δ_min: Parteli et al. (2014) closed form
  // of the quartic a⁴ − 2R*δ a² − k²R*² a + R*²δ² = 0 (c0 = m², c1 = −(kR*)², c2 = −2m with
  // m = R*δ), polished by one Newton step on δ(a) − δ = 0, which also removes the round-off of
  // the closed form (and of FastCbrt).
  DEMCAL_HOT_INLINE static Radius SolveRadius(double delta, double r_eff, double k) {
    const double inv_r_eff = 1.0 / r_eff;
    const double m = r_eff * delta;
    const double kr = k * r_eff, kr2 = kr * kr;
    const double p = -(4.0 / 3.0) * m * m;
    const double q = -(16.0 / 27.0) * m * m * m - 0.125 * kr2 * kr2;
    const double disc = 0.25 * q * q + (1.0 / 27.0) * p * p * p;
    const double u = FastCbrt(-0.5 * q + std::sqrt(std::max(0.0, disc)));
    const double s = u != 0.0 ? (5.0 / 3.0) * m + u - p / (3.0 * u) : (5.0 / 3.0) * m - FastCbrt(q);
    const double c2 = -2.0 * m;
    const double omega = std::sqrt(std::max(0.0, c2 + 2.0 * s));
    const double lambda = omega > 0 ? -kr2 / (2.0 * omega) : 0.0;
    Radius r{};
    r.a = 0.5 * (omega + std::sqrt(std::max(0.0, omega * omega - 4.0 * (c2 + s + lambda))));
    r.sqrt_a = std::sqrt(r.a);
    if (r.a > 0) {
      const double inv_sqrt_a = 1.0 / r.sqrt_a;
      const double f = r.a * r.a * inv_r_eff - k * r.sqrt_a - delta;
      const double df = 2.0 * r.a * inv_r_eff - 0.5 * k * inv_sqrt_a;
      if (df > 0) {
        const double step = f / df;
        r.a -= step;
        r.sqrt_a -= 0.5 * step * inv_sqrt_a;  // first order: the step is round-off sized
      }
    }
    return r;
  }

  // The same radius by Newton's method from s = √a of a nearby overlap (the last step's). In s,
  // R*δ(s) = s⁴ − kR* s is a polynomial (no roots or divisions by R*) and convex, so from any s on
  // the stable branch (slope > 0) the first step lands at or above the stable root and the
  // iterates descend to it quadratically. A step ds leaves an error of about 6s²ds²/slope
  // (Newton's error term, the curvature being 12s²); iteration stops once that is below
  // round-off, which after one step from the last step's s it usually is. Falls back to the
  // closed form off the branch or if it has not settled after a few steps.
  DEMCAL_HOT_INLINE static Radius RefineRadius(double delta, double r_eff, double k, double s) {
    constexpr int kMaxSteps = 6;
    constexpr double kTolerance = 1e-15;  // relative error left, round-off of s
    const double kr = k * r_eff, target = r_eff * delta;
    for (int step = 0; step < kMaxSteps; ++step) {
      const double s3 = s * s * s;
      const double slope = 4.0 * s3 - kr;
      if (!(slope > 0)) break;
      const double ds = (s3 * s - kr * s - target) / slope;
      s -= ds;
      if (6.0 * s * ds * ds <= kTolerance * slope) return {s * s, s};
    }
    return SolveRadius(delta, r_eff, k);
  }

  // Contact radius on the stable branch for overlap δ >= δ_min (SolveRadius).
  static double ContactRadius(double delta, double r_eff, double e_star, double gamma) {
    return SolveRadius(delta, r_eff, AdhesionLength(e_star, gamma)).a;
  }

  // h.jkr_sqrt_radius carries √a from step to step (0: a new contact, solved in closed form).
  DEMCAL_HOT_INLINE static NormalForce Compute(const ContactGeometry& g, const ResolvedPair& p,
                                               ContactHistory& h) {
    const double gamma = p.interfacial_energy_J_m2;
    if (gamma <= 0) return HertzMindlinNormal::Compute(g, p, h);
    constexpr double kTwoSqrtFiveSixths = 1.8257418583505538;
    const double e_star = p.effective_youngs_Pa, r_eff = g.effective_radius_m;
    const double k = p.jkr_adhesion_length;  // AdhesionLength, resolved once per pair
    const auto [a, sqrt_a] = h.jkr_sqrt_radius > 0
                                 ? RefineRadius(g.overlap_m, r_eff, k, h.jkr_sqrt_radius)
                                 : SolveRadius(g.overlap_m, r_eff, k);
    h.jkr_sqrt_radius = sqrt_a;
    const double hertz = (4.0 / 3.0) * e_star * a * (g.overlap_m + k * sqrt_a);  // a²/R* = δ + k√a
    const double adhesion = 2.0 * k * e_star * a * sqrt_a;  // 4 sqrt(πΓE*) a^{3/2}
    const double s_n = 2.0 * e_star * a;
    const double c_n = -kTwoSqrtFiveSixths * p.beta * std::sqrt(s_n * g.effective_mass_kg);
    const double v_n = Dot(g.relative_velocity_m_s, g.normal);
    NormalForce n{};
    n.elastic_N = hertz - adhesion;
    n.total_N = n.elastic_N - c_n * v_n;
    n.stiffness_n = s_n;
    n.secant_kn = (4.0 / 3.0) * e_star * a;
    n.contact_radius_m = a;
    n.friction_load_N = hertz;
    n.rolling_load_N = hertz;
    n.damping_N_s_m = c_n;
    return n;
  }
};

}  // namespace demcal::core
