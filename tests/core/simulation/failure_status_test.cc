// Failures are reported as a status, never as a crash or a hang (simulation.h, run_summary.h;
// docs/design.md: IsValid for bad configuration before any work, a termination status for runtime
// outcomes).
#include <catch2/catch.hpp>
#include <string>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

// A closed 4 × 4 × 8 cm box with 300 spheres of 4 mm falling into it.
Scene GranularBox() {
  Scene s;
  s.materials = {{"grain", 1e8, 0.25, 2500}};
  s.species = {{"grain", 0, {}}};
  s.species[0].size.diameter_m = 0.004;
  s.pair_parameters = {PairParameters{0.5, 0.1, 0.5, 0}};
  s.rolling.name = "epsd";
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.04, 0.04, 0.08}, 0, /*open_top=*/false);
  s.domain_min_m = {-0.01, -0.01, -0.01};
  s.domain_max_m = {0.05, 0.05, 0.09};
  s.fills = {{0, {0, 0, 0}, {0.04, 0.04, 0.08}, 300, {0, 0, -0.5}}};
  return s;
}

}  // namespace

TEST_CASE("Scene::IsValid rejects a time step above the Rayleigh time", "[unit]") {
  Scene s = GranularBox();
  const double t_r = RayleighTime(s);
  s.time.timestep_s = 2 * t_r;
  std::string err;
  CHECK_FALSE(s.IsValid(&err));
  INFO(err);
  CHECK(err.find("time.timestep_s") != std::string::npos);
  // Initialize refuses it too, and Run then reports an invalid scene without running.
  Simulation sim(s, {.threads = 1});
  std::string init_err;
  CHECK_FALSE(sim.Initialize(&init_err));
  CHECK(init_err.find("time.timestep_s") != std::string::npos);
  const RunSummary r = sim.Run(0.01);
  CHECK(r.termination == Termination::kInvalidScene);
  CHECK(r.steps == 0);
  // Just below the Rayleigh time, or above it with force_timestep, the scene is valid.
  s.time.timestep_s = 0.99 * t_r;
  CHECK(s.IsValid(&err));
  s.time.timestep_s = 2 * t_r;
  s.time.force_timestep = true;
  CHECK(s.IsValid(&err));
}

TEST_CASE("a time step 50x the Rayleigh time ends in a blow-up status", "[unit]") {
  Scene s = GranularBox();
  s.time.timestep_s = 50 * RayleighTime(s);
  s.time.force_timestep = true;
  for (const int check_every : {1, 100}) {
    DYNAMIC_SECTION("checks every " << check_every << " steps") {
      Simulation sim(s, {.threads = 1, .check_every_steps = check_every});
      std::string err;
      const bool initialized = sim.Initialize(&err);
      INFO(err);
      REQUIRE(initialized);
      const RunSummary r = sim.Run(2000 * s.time.timestep_s);
      INFO(r.BriefReport());
      CHECK((r.termination == Termination::kEnergyBlowUp ||
             r.termination == Termination::kNonFinite));
      CHECK(r.steps < 2000);  // stopped early
      CHECK_FALSE(r.message.empty());
    }
  }
}

TEST_CASE("a particle launched out of an open box ends with particles_lost", "[unit]") {
  Scene s = GranularBox();
  s.fills.clear();
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.04, 0.04, 0.08}, 0, /*open_top=*/true);
  s.particles = {{0, {0.02, 0.02, 0.01}, {0.1, 0, 3.0}, {}, 0}};  // rises ~0.46 m
  Simulation sim(s, {.threads = 1});
  std::string err;
  const bool initialized = sim.Initialize(&err);
  INFO(err);
  REQUIRE(initialized);
  const RunSummary r = sim.Run(0.5);
  INFO(r.BriefReport());
  CHECK(r.termination == Termination::kParticlesLost);
  CHECK(r.simulated_time_s < 0.5);
  CHECK(r.message.find("left the domain") != std::string::npos);
}
