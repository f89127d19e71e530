// A sphere launched without spin on a flat wall slides, then rolls (docs/physics.md §2, "Analytic
// rolling checks"). While sliding, kinetic friction μ m g decelerates the centre and spins the
// sphere up: v(t) = v0 − μ g t, R ω(t) = (5/2) μ g t. The slip velocity v − R ω vanishes at
// t* = 2 v0 / (7 μ g), after which the sphere rolls at v = (5/7) v0 (no rolling resistance).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "core/simulation/simulation.h"

using namespace demcal::core;

TEST_CASE("a sphere launched without spin slides, then rolls at 5/7 of its speed", "[physics]") {
  const double g = 9.81, mu = 0.3, v0 = 1.0, r = 0.005;
  const Material m{"glass", 1e8, 0.25, 2500};
  Scene s;
  s.materials = {m};
  s.species = {{"sphere", 0, {}}};
  s.species[0].size.diameter_m = 2 * r;
  PairParameters pp;
  pp.sliding_friction = mu;
  pp.restitution = 0.5;
  s.pair_parameters = {pp};
  s.rolling.name = "none";
  s.gravity_m_s2 = {0, 0, -g};
  s.walls = {PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}};
  // Start at the static Hertz overlap, m g = (4/3) E* sqrt(R) δ^{3/2}, so the sphere does not
  // bounce (E* = E/(2(1 − ν²)) for a wall of the same material).
  const double mass = m.density_kg_m3 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double e_star = m.youngs_modulus_Pa / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
  const double overlap = std::pow(mass * g / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
  s.particles = {{0, {0, 0, r - overlap}, {v0, 0, 0}, {}, 2 * r}};
  s.domain_min_m = {-0.02, -0.02, -0.02};  // small: the cell grid spans the domain
  s.domain_max_m = {0.2, 0.02, 0.02};
  s.time.timestep_s = 1e-5;

  Simulation sim(s, {.threads = 1});
  std::string err;
  const bool initialized = sim.Initialize(&err);
  INFO(err);
  REQUIRE(initialized);

  const double t_star = 2 * v0 / (7 * mu * g);  // 0.09708 s
  double t_roll = -1;                           // first time |v − R ω| < 1e-3 v0
  double v_half = 0;                            // v at t*/2, during sliding
  Simulation::Observer obs;
  obs.every_steps = 1;
  obs.callback = [&](const Simulation& q) {
    const Particles& p = q.particles();
    const double slip = p.velocity_m_s[0].x - r * p.angular_velocity_rad_s[0].y;
    if (t_roll < 0 && std::abs(slip) < 1e-3 * v0) t_roll = q.time_s();
    if (v_half == 0 && q.time_s() >= 0.5 * t_star) v_half = p.velocity_m_s[0].x;
    return true;
  };
  const RunSummary run = sim.Run(2 * t_star, obs);
  INFO(run.BriefReport());
  REQUIRE(run.ok());

  const Particles& p = sim.particles();
  INFO("t_roll = " << t_roll << " s vs 2 v0/(7 μ g) = " << t_star << " s");
  INFO("v(t*/2) = " << v_half << " vs " << v0 - mu * g * 0.5 * t_star);
  INFO("final v = " << p.velocity_m_s[0].x << ", R ω = " << r * p.angular_velocity_rad_s[0].y
                    << " vs 5/7 v0 = " << 5.0 / 7.0 * v0);
  CHECK(v_half == Approx(v0 - mu * g * 0.5 * t_star).epsilon(0.01));
  CHECK(t_roll == Approx(t_star).epsilon(0.01));
  CHECK(p.velocity_m_s[0].x == Approx(5.0 / 7.0 * v0).epsilon(0.01));
  CHECK(r * p.angular_velocity_rad_s[0].y == Approx(5.0 / 7.0 * v0).epsilon(0.01));
}
