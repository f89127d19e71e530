// Velocity Verlet inside the force sweep (contact_forces.h, SweepUpdate): between checks the
// sweep kicks each free sphere twice and drifts it as soon as its force is complete, and answers
// the next rebuild check; at a check step it kicks once and the next step's own pass does the
// rest. Both are the same floating-point operations in the same order, so a run that checks
// every step (the sweep never drifts) must end in exactly the state of one that checks every
// 100 steps (it nearly always does), with one thread and with three (spheres read by another
// chunk's cross pairs are moved after the sweep). A drift done before a partner read the old
// position, a kick from an incomplete force or a missed rebuild would each show as a difference.
#include <catch2/catch.hpp>
#include <string>

#include "core/math/random.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

// 1,200 overlapping, jostling spheres in a closed box: pairs cross the chunk boundaries and the
// list is rebuilt many times in 0.02 s.
Scene JostlingBox() {
  Scene s;
  s.materials = {{"grain", 1e7, 0.25, 2500}, {"steel", 2e9, 0.3, 7800}};
  s.species = {{"grain", 0, {}}};
  s.species[0].size = {SizeDistribution::Kind::kUniform, 0, 0.003, 0.005, {}, {}};
  const PairParameters grain_grain{0.5, 0.1, 0.5, 0};
  const PairParameters grain_wall{0.4, 0.05, 0.6, 0};
  s.pair_parameters = {grain_grain, grain_wall, grain_wall, grain_grain};
  s.rolling.name = "epsd";
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.04, 0.04, 0.12}, 1, /*open_top=*/false);
  s.domain_min_m = {-0.01, -0.01, -0.01};
  s.domain_max_m = {0.05, 0.05, 0.13};
  s.seed = 11;
  Rng rng(3);
  const double d = 0.004, pitch = 0.97 * d;
  for (int z = 0; z < 12; ++z)
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x) {
        const Vec3 at{0.0025 + pitch * x, 0.0025 + pitch * y, 0.0025 + pitch * z};
        const Vec3 v{rng.Uniform() - 0.5, rng.Uniform() - 0.5, rng.Uniform() - 0.5};
        s.particles.push_back({0, at, 0.2 * v, 50.0 * v, d, {}});
      }
  return s;
}

struct Outcome {
  Particles state;
  uint64_t rebuilds = 0;
};

Outcome RunJostling(int threads, int check_every_steps) {
  Simulation sim(JostlingBox(), {.threads = threads, .check_every_steps = check_every_steps});
  std::string err;
  const bool initialized = sim.Initialize(&err);
  INFO(err);
  REQUIRE(initialized);
  const RunSummary run = sim.Run(0.02);
  INFO(run.BriefReport());
  REQUIRE(run.ok());
  return {sim.particles(), run.neighbour_rebuilds};
}

size_t Differing(const Particles& a, const Particles& b) {
  if (a.Size() != b.Size()) return a.Size() + b.Size();
  size_t differing = 0;
  for (size_t i = 0; i < a.Size(); ++i)
    differing += !(a.id[i] == b.id[i] && a.position_m[i] == b.position_m[i] &&
                   a.velocity_m_s[i] == b.velocity_m_s[i] &&
                   a.angular_velocity_rad_s[i] == b.angular_velocity_rad_s[i]);
  return differing;
}

}  // namespace

TEST_CASE("spheres moved in the force sweep end as when moved in passes of their own",
          "[unit][physics]") {
  const Outcome reference = RunJostling(1, 1);  // every step checked: no drift in the sweep
  REQUIRE(reference.state.Size() == 1200);
  CHECK(reference.rebuilds > 5);
  for (const int threads : {1, 3}) {
    const Outcome swept = RunJostling(threads, 100);
    INFO(threads << " thread(s)");
    CHECK(swept.rebuilds == reference.rebuilds);
    CHECK(Differing(swept.state, reference.state) == 0);
  }
  CHECK(Differing(RunJostling(3, 1).state, reference.state) == 0);
}
