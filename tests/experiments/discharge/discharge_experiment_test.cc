#include "experiments/discharge/discharge_experiment.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/simulation/simulation.h"
#include "experiments/discharge/hopper_fill.h"
#include "experiments/discharge/outflow_recorder.h"
#include "experiments/discharge/discharge_test_scenes.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

core::Scene Beads(double d_m) { return test::GlassBeads(d_m); }

DischargeSettings Funnel(double d_m, double orifice_m, double mass_kg) {
  return test::PlacedFunnel(d_m, orifice_m, mass_kg);
}

const core::Wall* FindWall(const core::Scene& scene, const std::string& name) {
  for (const core::Wall& w : scene.walls)
    if (w.name == name) return &w;
  return nullptr;
}

}  // namespace

TEST_CASE("discharge scene: funnel on the orifice plane, a closed gate, a catch floor below",
          "[unit]") {
  const double d = 0.002;
  DischargeSettings s = Funnel(d, 0.012, 0.01);
  s.gate_open_s = 0.7;
  s.hopper.cylinder_height_m = 0.01;
  std::string error;
  REQUIRE(s.IsValid(Beads(d), &error));
  const core::Scene scene = BuildDischargeScene(Beads(d), s, 5);
  REQUIRE(scene.IsValid(&error));
  const core::Wall* cone = FindWall(scene, "hopper.cone");
  REQUIRE(cone);
  const auto& frustum = std::get<core::ConeFrustumSurface>(cone->shape);
  CHECK(frustum.height0_m == 0);
  CHECK(frustum.radius0_m == Approx(0.006));
  CHECK(frustum.radius1_m == Approx(12 * d));
  CHECK(frustum.height1_m == Approx((12 * d - 0.006) / std::tan(std::numbers::pi / 6)));
  REQUIRE(FindWall(scene, "hopper.cylinder"));
  const core::Wall* gate = FindWall(scene, "gate");
  REQUIRE(gate);
  CHECK(gate->DisplacementAt(0.69).z == 0);
  CHECK(gate->DisplacementAt(0.71).z < 0);
  // The gate ends below the catch floor, and the grains falling behind it never reach it.
  const double travel = -gate->DisplacementAt(100).z;
  CHECK(travel > s.catch_depth_m);
  CHECK(2 * gate->velocity_m_s.z * gate->velocity_m_s.z / 9.81 > s.catch_depth_m);
  const core::Wall* floor = FindWall(scene, "catch.zmin");
  REQUIRE(floor);
  CHECK(std::get<core::PlaneSurface>(floor->shape).point_m.z == Approx(-s.catch_depth_m));
  CHECK(scene.domain_min_m.z < -s.catch_depth_m);
  // The placed fill is inside the domain; its geometry is tested below.
  REQUIRE(scene.particles.size() == static_cast<size_t>(PlacedCount(Beads(d), s.feed, {0, 1.0})));
  for (const core::ParticleSpec& p : scene.particles) CHECK(p.position_m.z < scene.domain_max_m.z);

  core::Scene opened = scene;
  OpenGateAt(1.5, &opened);
  CHECK(FindWall(opened, "gate")->DisplacementAt(1.49).z == 0);
  CHECK(FindWall(opened, "gate")->DisplacementAt(100).z == Approx(-travel));
}

TEST_CASE("placed fill: a loose lattice inside the hopper, clear of gate, cone and cylinder",
          "[unit]") {
  const double d = 0.002;
  DischargeSettings s = Funnel(d, 0.012, 0.01);
  s.hopper.cylinder_height_m = 0.01;
  const std::vector<core::ParticleSpec> fill = PlacedFill(Beads(d), s, 5);
  REQUIRE(fill.size() == static_cast<size_t>(PlacedCount(Beads(d), s.feed, {0, 1.0})));
  REQUIRE(fill.size() > 900);  // 0.01 kg of 2 mm glass beads
  const double half_angle = std::numbers::pi / 6, r0 = 0.006, r1 = 12 * d;
  double top = 0, gate = 1, cylinder = 1, cone = 1, gap = 1;  // least clearances, in d
  for (size_t i = 0; i < fill.size(); ++i) {
    const core::Vec3& x = fill[i].position_m;
    const double rho = std::hypot(x.x, x.y);
    gate = std::min(gate, x.z / d - 0.5);
    cylinder = std::min(cylinder, (r1 - rho) / d - 0.5);
    const double to_cone = x.z * std::sin(half_angle) - (rho - r0) * std::cos(half_angle);
    cone = std::min(cone, to_cone / d - 0.5);
    for (size_t j = 0; j < i; ++j) gap = std::min(gap, Norm(fill[j].position_m - x) / d - 1);
    top = std::max(top, x.z);
  }
  CHECK(gate >= 0);
  CHECK(cylinder >= 0);
  CHECK(cone >= 0);
  CHECK(gap >= 0);  // no overlaps
  CHECK(cone < 0.1);  // the lattice reaches down into the cone
  // Bottom-up at a solid fraction ≈ 0.39: the fill stays far below a fall from above the rim.
  CHECK(top < s.hopper.TopM() + 2 * d);
  CHECK(top + d == Approx(FillTopM(Beads(d), s)).margin(0.05 * 1.1 * d));
  // The seed moves the grains (jitter), not the lattice.
  const std::vector<core::ParticleSpec> other = PlacedFill(Beads(d), s, 6);
  REQUIRE(other.size() == fill.size());
  CHECK(Norm(other[0].position_m - fill[0].position_m) > 0);
  CHECK(Norm(other[0].position_m - fill[0].position_m) < 0.1 * d);
}

TEST_CASE("placed fill: a mixture's species are spread over the lattice in their proportions",
          "[unit]") {
  const double d = 0.002;
  core::Scene model = Beads(d);
  model.species.push_back(model.species[0]);
  model.species[1].name = "other";
  DischargeSettings s = Funnel(d, 0.012, 0.01);
  s.hopper.cylinder_height_m = 0.01;
  s.feed.components = {{0, 0.75}, {1, 0.25}};
  const std::vector<core::ParticleSpec> fill = PlacedFill(model, s, 5);
  const size_t n1 = static_cast<size_t>(PlacedCount(model, s.feed, s.feed.components[1]));
  size_t ones = 0, ones_low = 0;
  for (size_t i = 0; i < fill.size(); ++i) {
    ones += fill[i].species == 1;
    ones_low += fill[i].species == 1 && i < fill.size() / 2;
  }
  CHECK(ones == n1);
  // Shuffled: the bottom half holds about half of them (binomial, σ ≈ √(n1/4) ≈ 8).
  CHECK(std::abs(static_cast<double>(ones_low) - 0.5 * n1) < 5 * std::sqrt(0.25 * n1));
}

TEST_CASE("discharge settings: the orifice must pass 3 of the largest grains", "[unit]") {
  const double d = 0.004;
  std::string error;
  CHECK_FALSE(Funnel(d, 0.011, 0.01).IsValid(Beads(d), &error));
  CHECK(error.find("discharge.hopper.orifice_diameter_m") != std::string::npos);
  CHECK(Funnel(d, 0.013, 0.01).IsValid(Beads(d), &error));
  CHECK_FALSE(Funnel(d, 0.013, 5.0).IsValid(Beads(d), &error));
  CHECK(error.find("discharge.feed.mass_kg") != std::string::npos);
}

TEST_CASE("hopper bulk density: one grain per cubic cell gives mass over cell volume", "[unit]") {
  const HopperGeometry h{.top_diameter_m = 0.1, .orifice_diameter_m = 0.02,
                         .cone_half_angle_deg = 30, .cylinder_height_m = 0.05};
  // A jittered lattice (one grain at a random place in each cell): any region holds on average
  // its volume over a³ grains, so only the cells cut by the probe's boundary add noise.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  core::Particles p;
  const double a = 0.002, m = 1e-5;
  for (double x = -0.05; x < 0.05; x += a)
    for (double y = -0.05; y < 0.05; y += a)
      for (double z = 0; z < h.TopM(); z += a)
        p.Add(static_cast<int64_t>(p.Size()), 0, 0, 0.0005, 1000,
              {x + a * u(rng), y + a * u(rng), z + a * u(rng)}, {}, {});
  for (size_t i = 0; i < p.Size(); ++i) p.mass_kg[i] = m;
  CHECK(HopperBulkDensity(p, h, 0.002) == Approx(m / (a * a * a)).epsilon(0.01));
}

TEST_CASE("outflow recorder: a grain counts once, when its centre first drops below the plane",
          "[unit]") {
  core::Scene scene = Beads(0.002);
  scene.domain_min_m = {-0.1, -0.1, -0.1};
  scene.domain_max_m = {0.1, 0.1, 0.1};
  scene.particles = {{.species = 0, .position_m = {0, 0, 0.01}},
                     {.species = 0, .position_m = {0.01, 0, 0.01}}};
  core::Simulation sim(scene, {.threads = 1});
  std::string error;
  REQUIRE(sim.Initialize(&error));
  OutflowRecorder recorder(1, 0.0);
  recorder.Sample(sim);
  CHECK(recorder.remaining_count() == 2);
  CHECK(recorder.total_out_kg() == 0);
  const double m = sim.particles().mass_kg[0];
  sim.mutable_particles().position_m[0].z = -0.001;
  recorder.Sample(sim);
  sim.mutable_particles().position_m[0].z = 0.001;  // bounced back up
  recorder.Sample(sim);
  sim.mutable_particles().position_m[0].z = -0.002;
  recorder.Sample(sim);
  CHECK(recorder.total_out_kg() == Approx(m));
  CHECK(recorder.remaining_count() == 1);
  REQUIRE(recorder.samples().size() == 4);
  CHECK(recorder.samples()[1].cumulative_mass_kg[0] == Approx(m));
}
