#include "objectives/common/settled_run.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>

#include "core/simulation/simulation.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

// Two species of 4 mm grains in an empty box without gravity (nothing changes while measured):
// species 0 a sphere, species 1 a rigid clump of two touching 4 mm spheres.
core::Scene Grains() {
  core::Scene s;
  s.materials = {{"m", 1e7, 0.25, 2000}};
  s.species = {{"sphere", 0, {}, {}}, {"pair", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.004;
  s.species[1].size.diameter_m = 0.004;
  s.species[1].clump_shape = {{{-0.25, 0, 0}, 0.5}, {{0.25, 0, 0}, 0.5}};
  s.pair_parameters = {core::PairParameters{}};
  s.gravity_m_s2 = {0, 0, 0};
  s.domain_min_m = {-1, -1, -1};
  s.domain_max_m = {1, 1, 1};
  s.time.duration_s = 1;
  return s;
}

std::unique_ptr<core::Simulation> Initialized(const core::Scene& scene) {
  auto sim = std::make_unique<core::Simulation>(scene, core::Simulation::Options{.threads = 1});
  std::string error;
  REQUIRE(sim->Initialize(&error));
  return sim;
}

}  // namespace

TEST_CASE("specific kinetic energy: mass-weighted, rotation included, fixed grains left out",
          "[unit]") {
  core::Scene scene = Grains();
  // 1 grain at rest, 1 moving at 0.02 m/s, 1 glued (would double the mass if counted).
  scene.particles = {{.species = 0, .position_m = {0, 0, 0}},
                     {.species = 0, .position_m = {0.1, 0, 0}, .velocity_m_s = {0, 0.02, 0}},
                     {.species = 0, .position_m = {0.2, 0, 0}, .fixed = true}};
  // ½ m v² over 2 m: 1e-4 J/kg.
  CHECK(SpecificKineticEnergy(*Initialized(scene)) == Approx(1e-4).epsilon(1e-12));

  // A spinning sphere adds ½ I ω² with I = m d²/10.
  scene.particles[0].angular_velocity_rad_s = {0, 0, 10};
  const double rotation = 0.5 * 0.004 * 0.004 / 10 * 100 / 2;  // ½ I ω² / (2 m), J/kg
  CHECK(SpecificKineticEnergy(*Initialized(scene)) == Approx(1e-4 + rotation).epsilon(1e-9));
}

TEST_CASE("specific kinetic energy: a clump's mass counts once, not once per member", "[unit]") {
  core::Scene scene = Grains();
  scene.particles = {{.species = 1, .position_m = {0, 0, 0}, .velocity_m_s = {0.02, 0, 0}},
                     {.species = 0, .position_m = {0.1, 0, 0}}};
  const auto sim = Initialized(scene);
  REQUIRE(sim->system().clumps.Size() == 1);
  const double clump_kg = sim->system().clumps.mass_kg[0];
  double sphere_kg = 0;  // the free sphere's slot (the members carry the clump's mass)
  for (size_t i = 0; i < sim->particles().Size(); ++i)
    if (sim->particles().body[i] < 0) sphere_kg = sim->particles().mass_kg[i];
  REQUIRE(sphere_kg > 0);
  CHECK(SpecificKineticEnergy(*sim) ==
        Approx(0.5 * clump_kg * 0.02 * 0.02 / (clump_kg + sphere_kg)).epsilon(1e-9));
}

TEST_CASE("specific kinetic energy: no moving mass gives 0, a blown-up state never settles",
          "[unit]") {
  core::Scene scene = Grains();
  scene.particles = {{.species = 0, .position_m = {0, 0, 0}, .fixed = true}};
  CHECK(SpecificKineticEnergy(*Initialized(scene)) == 0);

  scene.particles = {{.species = 0, .position_m = {0, 0, 0}}};
  const auto sim = Initialized(scene);
  sim->mutable_particles().velocity_m_s[0].x = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isnan(SpecificKineticEnergy(*sim)));
  // RunUntilSettled compares `energy < threshold`, false for NaN: a NaN state is not settled
  // (the engine reports it as non_finite first).
  const SettleResult settled = RunUntilSettled(*sim, {.max_time_s = 0.05}, {});
  CHECK_FALSE(settled.ok());
}

TEST_CASE("run until settled: a grain on a floor settles, a pour cut short does not", "[unit]") {
  core::Scene scene = Grains();
  scene.gravity_m_s2 = {0, 0, -9.81};
  scene.pair_parameters[0].restitution = 0.3;
  scene.walls = {core::PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}};
  scene.particles = {{.species = 0, .position_m = {0, 0, 0.01}}};
  {
    const auto sim = Initialized(scene);
    const SettleResult r =
        RunUntilSettled(*sim, {.specific_kinetic_J_kg = 1e-8, .max_time_s = 1, .surface_window_s = 0}, {});
    INFO(r.message);
    CHECK(r.ok());
    CHECK(r.specific_kinetic_J_kg < 1e-8);
    // It fell 8 mm (½v² ≈ 0.08 J/kg at impact), so settling takes at least the fall time.
    CHECK(r.settle_time_s > std::sqrt(2 * 0.008 / 9.81));
    CHECK(r.settle_time_s < 1);
  }
  {
    // Still falling when time is up.
    const auto sim = Initialized(scene);
    const SettleResult r =
        RunUntilSettled(*sim, {.specific_kinetic_J_kg = 1e-8, .max_time_s = 0.02}, {});
    CHECK(r.status == "not_settled");
    CHECK(r.message.find("not settled after 0.02 s") != std::string::npos);
  }
}

TEST_CASE("run until settled: a bed whose surface stopped changing settles at any energy scale",
          "[unit]") {
  // 60 grains dropped into a 3 cm box: with an unreachable energy threshold only the scale-free
  // surface criterion can end the run (settled_run.h).
  core::Scene scene = Grains();
  scene.gravity_m_s2 = {0, 0, -9.81};
  scene.pair_parameters[0].restitution = 0.3;
  scene.pair_parameters[0].sliding_friction = 0.5;
  scene.walls = core::BoxInnerFaces("box", {0, 0, 0}, {0.03, 0.03, 0.1}, 0, true);
  scene.fills = {{0, {0, 0, 0}, {0.03, 0.03, 0.05}, 60}};
  core::Scene moving = scene;
  {
    const auto sim = Initialized(scene);
    const SettleResult r = RunUntilSettled(
        *sim, {.specific_kinetic_J_kg = 1e-30, .max_time_s = 2, .surface_window_s = 0.1}, {});
    INFO(r.message);
    CHECK(r.ok());
    CHECK(r.settled_by == "surface");
    CHECK(r.surface_change_d < 0.02);
    CHECK(r.settle_time_s > 0.2);  // two windows after the first surface at least
    CHECK(r.settle_time_s < 2);
  }
  {  // the same without the surface criterion never settles
    const auto sim = Initialized(scene);
    const SettleResult r = RunUntilSettled(
        *sim, {.specific_kinetic_J_kg = 1e-30, .max_time_s = 0.5, .surface_window_s = 0}, {});
    CHECK(r.status == "not_settled");
  }
  {  // a grain sliding across a frictionless floor keeps changing the surface
    moving.fills.clear();
    moving.pair_parameters[0].sliding_friction = 0;
    moving.walls = {core::PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}};
    moving.particles = {{.species = 0, .position_m = {0, 0, 0.002}, .velocity_m_s = {0.2, 0, 0}}};
    const auto sim = Initialized(moving);
    const SettleResult r = RunUntilSettled(
        *sim, {.specific_kinetic_J_kg = 1e-30, .max_time_s = 0.6, .surface_window_s = 0.1}, {});
    INFO(r.message);
    CHECK(r.status == "not_settled");
    CHECK(r.surface_change_d > 0.02);
  }
}
