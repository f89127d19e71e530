// The sjkr normal law (core/contact/sjkr.h), LIGGGHTS-PUBLIC 3.8's `cohesion sjkr`: Hertz–Mindlin
// less k·π a², a the radius of the circle where the two sphere surfaces intersect. The circle is
// computed here the textbook way (Weisstein, "Sphere-Sphere Intersection", MathWorld, Eqs. 5–8):
// its plane lies x = (r² − R_j² + R_i²)/(2r) from i's centre, so a² = R_i² − x²; against a wall,
// the plane is the wall at distance R − δ, a² = R² − (R − δ)². The law evaluates the same circle
// in another, factored form, so the comparison checks the algebra. A sphere resting on a floor
// under sjkr settles where Hertz's force less the cohesion carries its weight.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <variant>

#include "core/contact/contact_kernel.h"
#include "core/contact/normal_model.h"
#include "core/contact/rolling_none.h"
#include "core/walls/wall_test_support.h"

using namespace demcal::core;

namespace {

constexpr double kEStar = 5e7, kGStar = 4e7, kK = 2e5;  // Pa, Pa, J/m³

ContactGeometry Geometry(double overlap_m, double radius_i_m, double radius_j_m) {
  ContactGeometry g{};
  g.normal = {0, 0, 1};
  g.overlap_m = overlap_m;
  g.radius_i_m = radius_i_m;
  g.radius_j_m = radius_j_m;
  g.effective_radius_m =
      radius_j_m > 0 ? radius_i_m * radius_j_m / (radius_i_m + radius_j_m) : radius_i_m;
  g.effective_mass_kg = 1e-5;
  g.relative_velocity_m_s = {0.01, 0, -0.05};
  return g;
}

// a² of the intersection circle from the distance of its plane to i's centre (see the top).
double TextbookRadius2(double overlap_m, double radius_i_m, double radius_j_m) {
  if (radius_j_m == 0) {
    const double x = radius_i_m - overlap_m;
    return radius_i_m * radius_i_m - x * x;
  }
  const double r = radius_i_m + radius_j_m - overlap_m;
  const double x = (r * r - radius_j_m * radius_j_m + radius_i_m * radius_i_m) / (2 * r);
  return radius_i_m * radius_i_m - x * x;
}

}  // namespace

TEST_CASE("sjkr's cohesion is k times the area of the surfaces' intersection circle",
          "[unit][contact]") {
  const ResolvedPair p = MakeResolvedPair(kEStar, kGStar, -0.3, 0.5, 0.1, 0, kK);
  struct Case {
    double overlap, ri, rj;
  };
  // Equal and unequal spheres, small and large overlaps, and walls (rj = 0).
  for (const Case c : {Case{1e-7, 1e-3, 1e-3}, Case{2e-5, 1e-3, 1e-3}, Case{3e-6, 1e-3, 2.5e-4},
                       Case{4e-5, 5e-4, 2e-3}, Case{1e-6, 1e-3, 0}, Case{5e-5, 2e-3, 0}}) {
    const ContactGeometry g = Geometry(c.overlap, c.ri, c.rj);
    ContactHistory hs{}, hh{};
    const NormalForce s = SjkrNormal{}.Force(g, p, hs);
    const NormalForce h = HertzMindlinNormal{}.Force(g, p, hh);
    const double cohesion = kK * std::numbers::pi * TextbookRadius2(c.overlap, c.ri, c.rj);
    INFO("overlap " << c.overlap << " radii " << c.ri << ", " << c.rj);
    CHECK(h.total_N - s.total_N == Approx(cohesion).epsilon(1e-9));
    CHECK(h.elastic_N - s.elastic_N == Approx(cohesion).epsilon(1e-9));
    // LIGGGHTS' Coulomb limit and cdt rolling torque read the force without the cohesion.
    CHECK(s.friction_load_N == h.friction_load_N);
    CHECK(s.rolling_load_N == h.rolling_load_N);
    CHECK(s.damping_N_s_m == h.damping_N_s_m);
    CHECK(s.stiffness_n == h.stiffness_n);
  }
  // For small overlaps the circle is twice Hertz's contact area, a² → 2R*δ.
  const ContactGeometry small = Geometry(1e-9, 1e-3, 3e-4);
  CHECK(SjkrNormal::IntersectionRadius2(small) ==
        Approx(2 * small.effective_radius_m * small.overlap_m).epsilon(1e-5));
}

TEST_CASE("sjkr acts only while the spheres overlap", "[unit][contact]") {
  const ResolvedPair p = MakeResolvedPair(kEStar, kGStar, -0.3, 0.5, 0.1, 0, kK);
  using Model = ContactModel<SjkrNormal, RollingNone>;
  CHECK(Model::InContact(1e-9, false, 5e-4, p));
  // Separated, whether or not the pair touched last step: no contact, so no force at all.
  CHECK_FALSE(Model::InContact(0.0, true, 5e-4, p));
  CHECK_FALSE(Model::InContact(-1e-9, true, 5e-4, p));
  CHECK(SjkrNormal::BreakGap(5e-4, p) == 0);
  // At touching the circle is a point: the force starts from zero, with no jump.
  CHECK(SjkrNormal::IntersectionRadius2(Geometry(0, 1e-3, 1e-3)) == 0);
}

TEST_CASE("sjkr with k = 0 is Hertz-Mindlin, bit for bit", "[unit][contact]") {
  const ResolvedPair plain = MakeResolvedPair(kEStar, kGStar, -0.3, 0.5, 0.1, 0);
  for (const double rj : {1e-3, 0.0}) {
    const ContactGeometry g = Geometry(2e-6, 1e-3, rj);
    ContactHistory hs{}, hh{};
    const NormalForce s = SjkrNormal{}.Force(g, plain, hs);
    const NormalForce h = HertzMindlinNormal{}.Force(g, plain, hh);
    CHECK(s.total_N == h.total_N);
    CHECK(s.elastic_N == h.elastic_N);
    CHECK(s.friction_load_N == h.friction_load_N);
    CHECK(s.rolling_load_N == h.rolling_load_N);
  }
  CHECK(SjkrNormal::AttractionEnergyBound(1e-3, plain, 12) == 0);
}

TEST_CASE("a sphere on a floor with sjkr cohesion rests where Hertz less k·A carries its weight",
          "[physics]") {
  using namespace demcal::core::wall_test;
  constexpr double kRadius = 0.005, kG = 9.81, kCohesion = 1e5;  // m, m/s², J/m³
  Scene s = OneMaterialScene(2 * kRadius);
  s.pair_parameters[0].cohesion_energy_density_J_m3 = kCohesion;
  const double weight = SphereMass(s, kRadius) * kG;
  const Material& m = s.materials[0];
  const double e_star = m.youngs_modulus_Pa / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
  // Net upward force of the floor at overlap δ: Hertz less the cohesion over the cap circle. It
  // is −weight at δ = 0, falls, then rises for good, so it has one root: bisect for it.
  auto net = [&](double d) {
    return 4.0 / 3.0 * e_star * std::sqrt(kRadius) * std::pow(d, 1.5) -
           kCohesion * std::numbers::pi * (2 * kRadius * d - d * d) - weight;
  };
  double lo = 0, hi = 1e-3;
  for (int k = 0; k < 200; ++k) (net(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  const double rest = 0.5 * (lo + hi);
  const double hertz = HertzRestOverlap(s, kRadius, weight);
  REQUIRE(rest > 1.3 * hertz);  // the cohesion is strong enough here to matter

  s.walls = {PlaneWall{"floor", {}, {0, 0, 1}, 0, {}}};
  s.gravity_m_s2 = {0, 0, -kG};
  s.particles = {{0, {0, 0, kRadius - hertz}, {}, {}, 2 * kRadius, {}}};
  s.domain_min_m = {-0.2, -0.2, -0.2};
  s.domain_max_m = {0.2, 0.2, 0.2};
  Simulation sim(s, {.threads = 1});
  InitializeOrFail(sim);
  REQUIRE(sim.Run(0.05).ok());
  CHECK(sim.particles().position_m[0].z == Approx(kRadius - rest).margin(1e-3 * rest));
  CHECK(TotalWallForce(sim).z == Approx(-weight).epsilon(1e-6));
}
