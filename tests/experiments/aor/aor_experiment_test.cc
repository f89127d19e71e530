#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "experiments/aor/aor_experiment.h"
#include "objectives/common/fidelity.h"
#include "objectives/common/replicates.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

// A small, soft, fast model: 3 mm spheres (±10%), E = 5 MPa, CDT rolling friction (EDEM's
// standard model); material 1 is the wall.
core::Scene Model(double sliding, double rolling, double gamma_J_m2) {
  core::Scene m;
  m.materials = {{"grain", 5e6, 0.25, 1000}, {"wall", 5e6, 0.25, 1000}};
  m.species = {{"g", 0, {}}};
  m.species[0].size.kind = core::SizeDistribution::Kind::kUniform;
  m.species[0].size.min_diameter_m = 2.7e-3;
  m.species[0].size.max_diameter_m = 3.3e-3;
  core::PairParameters pp{sliding, rolling, 0.3, gamma_J_m2};
  core::PairParameters pw{0.5, 0.05, 0.3, 0};
  m.pair_parameters = {pp, pw, pw, pw};
  m.rolling.name = "cdt";
  return m;
}

AorSettings SmallSlotHeap() {
  AorSettings s;
  s.feed.components = {{0, 1.0}};
  s.feed.mass_kg = 0.010;  // ≈ 700 grains
  s.feed.mass_rate_kg_s = 0.05;
  s.width_m = 0.09;
  s.depth_m = 0.012;
  s.pour_height_m = 0.05;
  s.feed_width_m = 0.012;
  s.wall_material = 1;
  s.settle.max_time_s = 2.0;
  return s;
}

Summary Angles(const core::Scene& model, const AorSettings& settings, int replicates) {
  std::vector<double> angles(replicates, NAN);
  RunReplicates(replicates, 11, 0, [&](int r, uint64_t seed) {
    const AorRun run = RunAor(model, settings, seed, {});
    if (run.ok()) angles[r] = run.angle.angle_deg;
  });
  const Summary s = Summarise(angles);
  REQUIRE(s.n == replicates);  // every run settled and measured
  return s;
}

// Larger than the noise: the difference of two means beyond 3 combined standard errors.
void CheckSteeper(const Summary& high, const Summary& low) {
  INFO("high " << high.mean << " ± " << high.sem << ", low " << low.mean << " ± " << low.sem);
  CHECK(high.mean - low.mean > 3 * std::hypot(high.sem, low.sem));
}

}  // namespace

// Zhou et al. 2001 (Phys. Rev. E 64:021301) and docs/physics.md §4.3: the angle of repose increases
// with sliding and rolling friction; adhesion (JKR Γ) steepens heaps too (paper Fig. 6). For
// spheres, rolling resistance dominates (Zhou et al. 2002's fit has θ → 0 as μ_r → 0), so the
// sliding-friction effect is checked at a moderate μ_r, and from a slippery μ_s = 0.15: between
// 0.3 and 0.9 it is only ≈ 2° for spheres (Zhou et al. 2001: the angle saturates above μ_s ≈ 0.4),
// too close to three replicates' noise to be told apart reliably.
TEST_CASE("the repose angle grows with sliding friction, rolling friction and Γ", "[dem]") {
  const AorSettings heap = SmallSlotHeap();
  const int replicates = 3;
  const AorRun one = RunAor(Model(0.3, 0.1, 0), heap, 3, {});
  REQUIRE(one.ok());
  CHECK(one.angle.flanks.size() == 2);
  double mass = 0;  // all of the poured mass is in the heap (none lost, glued base excluded)
  for (const Grain& g : one.heap.grains) mass += g.mass_kg;
  CHECK(mass == Approx(heap.feed.mass_kg).epsilon(0.02));

  const Summary base = Angles(Model(0.3, 0.1, 0), heap, replicates);
  CheckSteeper(Angles(Model(0.9, 0.1, 0), heap, replicates), Angles(Model(0.15, 0.1, 0), heap, replicates));
  CheckSteeper(Angles(Model(0.3, 0.3, 0), heap, replicates), base);
  // Γ for a Cohesion number of 0.02 between two 3 mm grains (E* = E/(2(1 − ν²))).
  const double e_star = 5e6 / (2 * (1 - 0.25 * 0.25));
  const double gamma = GammaForCohesionNumber(0.02, e_star, 0.75e-3, 1000, 9.81);
  CheckSteeper(Angles(Model(0.3, 0.1, gamma), heap, replicates), base);
}

TEST_CASE("aor settings out of range name the field", "[unit]") {
  const core::Scene model = Model(0.5, 0.1, 0);
  AorSettings s = SmallSlotHeap();
  std::string error;
  REQUIRE(s.IsValid(model, &error));
  s.width_m = 0.02;
  CHECK_FALSE(s.IsValid(model, &error));
  CHECK_THAT(error, Catch::Contains("aor.width_m"));
  s = SmallSlotHeap();
  s.feed.components = {{0, 0.5}};
  CHECK_FALSE(s.IsValid(model, &error));
  CHECK_THAT(error, Catch::Contains("sum to 0.5"));
  s = SmallSlotHeap();
  s.settle.max_time_s = 0.1;
  CHECK_FALSE(s.IsValid(model, &error));
  CHECK_THAT(error, Catch::Contains("max_time_s"));
}

TEST_CASE("the aor scene holds a glued base, a box and a feed factory", "[unit]") {
  const core::Scene model = Model(0.5, 0.1, 0);
  int64_t fixed = 0;
  const core::Scene scene = BuildAorScene(model, SmallSlotHeap(), 5, &fixed);
  std::string error;
  CHECK(scene.IsValid(&error));
  CHECK(fixed == static_cast<int64_t>(scene.particles.size()));
  CHECK(fixed == 30 * 4);  // 90 mm × 12 mm at the 3 mm mean diameter
  for (const core::ParticleSpec& p : scene.particles) CHECK(p.fixed);
  CHECK(scene.walls.size() == 5);  // open-top box
  REQUIRE(scene.factories.size() == 1);
  CHECK(scene.factories[0].total_mass_kg == 0.010);
  CHECK(scene.factories[0].velocity_m_s.z <= 0);
}

TEST_CASE("aor: a clump feed species gets a glued base of spheres of its material", "[unit]") {
  // Fixed particles are spheres; the clump-count calibration pours clumps.
  core::Scene model = Model(0.5, 0.1, 0);
  model.species[0].clump_shape = {{{-0.5, 0, 0}, 0.6}, {{0.5, 0, 0}, 0.6}};  // a 2-sphere rod
  int64_t fixed = 0;
  const core::Scene scene = BuildAorScene(model, SmallSlotHeap(), 7, &fixed);
  REQUIRE(fixed > 0);
  REQUIRE(scene.species.size() == 2);
  const core::Species& base = scene.species[1];
  CHECK(base.clump_shape.empty());
  CHECK(base.material == model.species[0].material);
  CHECK(base.size.diameter_m == Approx(3e-3));  // the feed's mean sieve diameter
  for (const core::ParticleSpec& p : scene.particles) CHECK(p.species == 1);
  std::string error;
  CHECK(scene.IsValid(&error));
  INFO(error);
}

TEST_CASE("replicates share idle cores as simulation threads, with the same heap bit for bit", "[dem]") {
  CHECK(ThreadsPerReplicate(1, 2) == 2);
  CHECK(ThreadsPerReplicate(2, 2) == 1);
  CHECK(ThreadsPerReplicate(3, 2) == 1);
  CHECK(ThreadsPerReplicate(3, 8) == 2);
  CHECK(ThreadsPerReplicate(0, 4) == 4);
  CHECK(ThreadsPerReplicate(1, 0) >= 1);  // 0: all cores
  // core/simulation/simulation.h: every particle sums its contacts in serial order, so the thread count
  // changes nothing in the result.
  const core::Scene model = Model(0.5, 0.1, 0);
  RunHooks two;
  two.threads = 2;
  const AorRun a = RunAor(model, SmallSlotHeap(), 5, {}), b = RunAor(model, SmallSlotHeap(), 5, two);
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a.angle.angle_deg == b.angle.angle_deg);
  CHECK(a.settle.settle_time_s == b.settle.settle_time_s);
  REQUIRE(a.heap.grains.size() == b.heap.grains.size());
  for (size_t i = 0; i < a.heap.grains.size(); ++i) CHECK(a.heap.grains[i].position_m == b.heap.grains[i].position_m);
}
