// Energy conservation of an elastic, frictionless granular gas. With e = 1 (β = 0, no dashpot),
// μ_s = 0 and no rolling resistance, every contact force is the conservative Hertz force, whose
// potential is U = (8/15) E* sqrt(R*) δ^{5/2} (the integral of (4/3) E* sqrt(R*) δ^{3/2},
// docs/physics.md §1.2). With gravity off, kinetic + contact elastic energy is a constant of
// motion; velocity Verlet keeps it to a bounded error with no secular drift.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

// Σ over touching sphere pairs and sphere–wall contacts of (8/15) E* sqrt(R*) δ^{5/2}; one
// material, so E* = E/(2(1 − ν²)) for both kinds of contact; R* = R for a wall.
double ElasticEnergy(const Simulation& sim) {
  const Scene& s = sim.scene();
  const Material& m = s.materials[0];
  const double e_star = m.youngs_modulus_Pa / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
  const Particles& p = sim.particles();
  auto hertz = [&](double r_star, double overlap) {
    return overlap > 0 ? 8.0 / 15.0 * e_star * std::sqrt(r_star) * std::pow(overlap, 2.5) : 0.0;
  };
  double u = 0;
  for (size_t i = 0; i < p.Size(); ++i) {
    for (size_t j = i + 1; j < p.Size(); ++j) {
      const double rsum = p.radius_m[i] + p.radius_m[j];
      u += hertz(p.radius_m[i] * p.radius_m[j] / rsum,
                 rsum - Norm(p.position_m[i] - p.position_m[j]));
    }
    for (const Wall& w : s.walls) {
      const PlaneSurface& plane = std::get<PlaneSurface>(w.shape);
      u += hertz(p.radius_m[i], p.radius_m[i] - Dot(p.position_m[i] - plane.point_m, plane.normal));
    }
  }
  return u;
}

}  // namespace

TEST_CASE("an elastic frictionless gas conserves kinetic plus contact energy", "[physics][slow]") {
  const double box = 0.06;
  Scene s;
  s.materials = {{"elastic", 1e8, 0.25, 2500}};
  s.species = {{"sphere", 0, {}}};
  s.species[0].size = {SizeDistribution::Kind::kUniform, 0, 0.004, 0.006, {}, {}};
  PairParameters pp;
  pp.restitution = 1.0;
  pp.sliding_friction = 0.0;
  pp.rolling_friction = 0.0;
  s.pair_parameters = {pp};
  s.rolling.name = "none";
  s.gravity_m_s2 = {0, 0, 0};
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {box, box, box}, 0, /*open_top=*/false);
  s.domain_min_m = {-0.01, -0.01, -0.01};
  s.domain_max_m = {box + 0.01, box + 0.01, box + 0.01};
  // 216 spheres on a 6×6×6 lattice (spacing 10 mm > largest diameter), random velocities.
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> velocity(0, 1.0);
  std::uniform_real_distribution<double> diameter(0.004, 0.006), spin(-100, 100);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        s.particles.push_back({0,
                               {0.005 + 0.01 * i, 0.005 + 0.01 * j, 0.005 + 0.01 * k},
                               {velocity(rng), velocity(rng), velocity(rng)},
                               {spin(rng), spin(rng), spin(rng)},
                               diameter(rng)});
  // Contacts last ~35 steps at 10 % of the Rayleigh time. Velocity Verlet's energy error is
  // not smooth across contact start/end, so it random-walks from collision to collision
  // (~20 000 collisions here); measured: largest deviation 1.6e-4 at 10 %, 9.2e-4 at the
  // default 20 %.
  s.time.rayleigh_fraction = 0.1;

  Simulation sim(s, {.threads = 1});
  std::string err;
  const bool initialized = sim.Initialize(&err);
  INFO(err);
  REQUIRE(initialized);
  const double e0 = sim.KineticEnergy() + ElasticEnergy(sim);
  double worst = 0;
  size_t contacts_seen = 0;
  Simulation::Observer obs;
  obs.every_steps = 1000;
  obs.callback = [&](const Simulation& q) {
    const double e = q.KineticEnergy() + ElasticEnergy(q);
    worst = std::max(worst, std::abs(e - e0) / e0);
    contacts_seen += q.ActiveContacts();
    return true;
  };
  const RunSummary run = sim.Run(100000 * sim.timestep_s(), obs);
  INFO(run.BriefReport());
  REQUIRE(run.ok());
  REQUIRE(run.steps == 100000);
  const double e1 = sim.KineticEnergy() + ElasticEnergy(sim);
  INFO("E0 = " << e0 << " J, E(end) = " << e1 << " J");
  INFO("largest relative deviation " << worst);
  CHECK(contacts_seen > 0);  // the gas did collide
  CHECK(std::abs(e1 - e0) / e0 < 1e-3);
  CHECK(worst < 1e-3);
}
