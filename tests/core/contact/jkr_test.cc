// JKR adhesion (EDEM convention, w = 2Γ): model landmarks and DEM behaviour.
// Expected values: docs/physics.md §3.2 / §4.2, derived from Johnson, Kendall & Roberts (1971) with
// w = 2Γ: F_c = (3/2)π w R* = 3πΓR*; F(δ=0) = −(8/9)F_c; min F = −F_c; displacement-controlled
// snap-off at δ_min = −(3/4)(π²w²R*/E*²)^{1/3} with F = −(5/9)F_c; sticking velocity
// v_s = sqrt(2 W_sep/m*), W_sep = 7.092 (w⁵R*⁴/E*²)^{1/3}.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/contact/jkr.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 1e-3, kE = 5.333e7, kGamma = 0.05;  // R* (m), E* (Pa), Γ (J/m²)

double ForceAt(double delta) {
  ContactGeometry g{};
  g.normal = {0, 0, 1};
  g.overlap_m = delta;
  g.effective_radius_m = kR;
  g.effective_mass_kg = 1e-5;
  const ResolvedPair p = MakeResolvedPair(kE, kE, 0.0, 0.5, 0.0, kGamma);
  ContactHistory h{};
  return JkrNormal::Compute(g, p, h).elastic_N;
}

double DeltaOfA(double a) { return a * a / kR - std::sqrt(4 * kPi * kGamma * a / kE); }

}  // namespace

TEST_CASE("JKR force landmarks with w = 2 Gamma", "[physics][jkr]") {
  const double f_c = 3 * kPi * kGamma * kR;
  CHECK(ForceAt(0.0) == Approx(-8.0 / 9.0 * f_c).epsilon(1e-9));
  const double delta_min = -JkrNormal::BreakGap(kR, kE, kGamma);
  const double w = 2 * kGamma;
  CHECK(delta_min == Approx(-0.75 * std::cbrt(kPi * kPi * w * w * kR / (kE * kE))).epsilon(1e-12));
  CHECK(JkrNormal::Holds(-delta_min * (1 - 1e-9), kR, kE, kGamma));
  CHECK_FALSE(JkrNormal::Holds(-delta_min * (1 + 1e-9), kR, kE, kGamma));
  CHECK(ForceAt(delta_min * (1 - 1e-9)) == Approx(-5.0 / 9.0 * f_c).epsilon(1e-4));
  // Minimum of F over the stable branch = −F_c (scan δ from δ_min to a few |δ_min|).
  double f_min = 0;
  for (int k = 0; k <= 20000; ++k) f_min = std::min(f_min, ForceAt(delta_min * (1 - k * 1e-4)));
  CHECK(f_min == Approx(-f_c).epsilon(1e-5));
}

TEST_CASE("JKR contact radius solves the JKR relation on the stable branch", "[unit][jkr]") {
  const double delta_min = -JkrNormal::BreakGap(kR, kE, kGamma);
  for (double scale : {0.999, 0.5, 0.0, -0.3, -1.0, -3.0, -30.0}) {
    const double delta = scale * delta_min;
    const double a = JkrNormal::ContactRadius(delta, kR, kE, kGamma);
    CHECK(DeltaOfA(a) == Approx(delta).margin(1e-9 * std::abs(delta_min)));
    const double a_snap = std::cbrt(kPi * 2 * kGamma * kR * kR / (8 * kE));  // δ minimum
    CHECK(a >= a_snap * (1 - 1e-6));
  }
}

TEST_CASE("JKR radius refined from the last step equals the closed form", "[unit][jkr]") {
  const double delta_min = -JkrNormal::BreakGap(kR, kE, kGamma);
  const double k = JkrNormal::AdhesionLength(kE, kGamma);
  const double a_snap = std::cbrt(kPi * 2 * kGamma * kR * kR / (8 * kE));  // δ minimum
  // A loading–unloading path in small steps, as a contact sees it, then jumps across the range.
  std::vector<double> path;
  for (int n = 0; n <= 400; ++n) path.push_back(delta_min * (1 - 1e-9) * (1 - n * 0.01));
  for (int n = 400; n >= 0; --n) path.push_back(delta_min * (1 - 1e-9) * (1 - n * 0.01));
  for (double scale : {-30.0, 0.999, -3.0, 0.0, 0.5, -1.0}) path.push_back(scale * delta_min);
  double s = JkrNormal::SolveRadius(path[0], kR, k).sqrt_a;
  for (double delta : path) {
    const auto warm = JkrNormal::RefineRadius(delta, kR, k, s);
    const double a = JkrNormal::ContactRadius(delta, kR, kE, kGamma);
    // δ(a) is flat at the snap-off fold, so there a is fixed only to ~sqrt(round-off): compare
    // residuals everywhere and radii away from the fold.
    CHECK(DeltaOfA(warm.a) == Approx(delta).margin(1e-12 * std::abs(delta_min)));
    CHECK(warm.a >= a_snap * (1 - 1e-6));
    if (delta > 0.99 * delta_min) CHECK(warm.a == Approx(a).epsilon(1e-12));
    CHECK(warm.sqrt_a * warm.sqrt_a == Approx(warm.a).epsilon(1e-15));
    s = warm.sqrt_a;
  }
}

TEST_CASE("Gamma = 0 gives exactly Hertz-Mindlin", "[unit][jkr]") {
  ContactGeometry g{};
  g.normal = {0, 0, 1};
  g.overlap_m = 1e-6;
  g.effective_radius_m = kR;
  g.effective_mass_kg = 1e-5;
  g.relative_velocity_m_s = {0.01, 0, -0.1};
  const ResolvedPair p = MakeResolvedPair(kE, kE, -0.2, 0.5, 0.1, 0.0);
  ContactHistory hist_j{}, hist_h{};
  const NormalForce j = JkrNormal::Compute(g, p, hist_j), h = HertzMindlinNormal::Compute(g, p, hist_h);
  CHECK(j.total_N == h.total_N);
  CHECK(j.friction_load_N == h.friction_load_N);
  CHECK(j.contact_radius_m == h.contact_radius_m);
}

namespace {

// One sphere (R = 1 mm, E = 1e8 Pa, ν = 0.25 against the same wall material) above a floor.
Scene SphereOnFloor(double restitution, double gamma, double z, double vz, double dt) {
  Scene s;
  s.materials = {{"m", 1e8, 0.25, 2500}};
  s.species = {{"a", 0, {}}};
  s.species[0].size.diameter_m = 2 * kR;
  PairParameters pair;
  pair.restitution = restitution;
  pair.interfacial_energy_J_m2 = gamma;
  s.pair_parameters = {pair};
  s.rolling.name = "none";
  s.walls = {PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}};
  s.domain_min_m = {-0.01, -0.01, -0.01};
  s.domain_max_m = {0.01, 0.01, 0.05};
  s.gravity_m_s2 = {0, 0, 0};
  s.particles = {{0, {0, 0, z}, {0, 0, vz}, {}, 0}};
  s.time.timestep_s = dt;  // the Rayleigh time is 27 µs; the JKR contact period ~0.3 ms
  return s;
}

double WallEStar() { return 1e8 / (2 * (1 - 0.25 * 0.25)); }

}  // namespace

TEST_CASE("elastic JKR impact sticks below the sticking velocity and rebounds above",
          "[physics][jkr]") {
  const double e_star = WallEStar(), w = 2 * kGamma;
  const double mass = 2500 * 4.0 / 3.0 * kPi * kR * kR * kR;
  const double w_sep = 7.092 * std::cbrt(std::pow(w, 5) * std::pow(kR, 4) / (e_star * e_star));
  const double v_s = std::sqrt(2 * w_sep / mass);
  for (double factor : {0.97, 1.03}) {
    // Start just outside contact, moving towards the floor; e = 1 (no damping).
    Simulation sim(SphereOnFloor(1.0, kGamma, kR + 1e-9, -factor * v_s, 2e-7), {.threads = 1});
    std::string err;
    REQUIRE(sim.Initialize(&err));
    REQUIRE(sim.Run(2e-3).ok());  // many contact durations
    const double z = sim.particles().position_m[0].z;
    const double vz = sim.particles().velocity_m_s[0].z;
    const double gap = JkrNormal::BreakGap(kR, e_star, kGamma);
    if (factor < 1) {
      CHECK(z < kR + gap);  // still attached
    } else {
      CHECK(z > kR + gap);  // detached and flying away at the energy-balance speed
      CHECK(vz == Approx(std::sqrt(factor * factor - 1) * v_s).epsilon(0.02));
    }
  }
}

TEST_CASE("quasi-static pull-off from a wall equals F_c", "[physics][jkr]") {
  const double f_c = 3 * kPi * kGamma * kR;  // R* = R against a wall
  const double mass = 2500 * 4.0 / 3.0 * kPi * kR * kR * kR;
  Simulation sim(SphereOnFloor(0.3, kGamma, kR - 1e-9, 0, 1e-6), {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(5e-3).ok());  // settle into the adhesive equilibrium
  // Ramp a pulling body force slowly: detachment when m g_pull passes F_c.
  const double ramp_time = 1.0, steps_per_chunk = 200;
  const double g_final = 1.2 * f_c / mass;
  const double gap = JkrNormal::BreakGap(kR, WallEStar(), kGamma);
  double pull_at_break = -1;
  for (double t = 0; t < ramp_time; t += steps_per_chunk * sim.timestep_s()) {
    const double g = g_final * t / ramp_time;
    sim.SetGravity({0, 0, g});
    REQUIRE(sim.Run(steps_per_chunk * sim.timestep_s()).ok());
    if (sim.particles().position_m[0].z > kR + gap) {
      pull_at_break = mass * g;
      break;
    }
  }
  CHECK(pull_at_break == Approx(f_c).epsilon(0.01));
}
