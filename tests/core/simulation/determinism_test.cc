// Determinism across thread counts (simulation.h, contact_forces.h: each particle sums its
// contact slots in a fixed order, so results are bit-identical for any number of threads;
// docs/design.md, Conventions). A few hundred frictional spheres with EPSD rolling resistance are
// poured into a box with 1 and with 2 worker threads; every particle's state must match exactly.
#include <catch2/catch.hpp>
#include <string>

#include "core/math/random.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

Scene PouredBox() {
  Scene s;
  s.materials = {{"grain", 1e7, 0.25, 2500}, {"steel", 2e9, 0.3, 7800}};
  s.species = {{"grain", 0, {}}};
  s.species[0].size = {SizeDistribution::Kind::kUniform, 0, 0.003, 0.005, {}, {}};
  PairParameters grain_grain{0.5, 0.1, 0.5, 0};
  PairParameters grain_wall{0.4, 0.05, 0.6, 0};
  s.pair_parameters = {grain_grain, grain_wall, grain_wall, grain_grain};
  s.rolling.name = "epsd";
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.04, 0.04, 0.12}, 1, /*open_top=*/false);
  s.domain_min_m = {-0.01, -0.01, -0.01};
  s.domain_max_m = {0.05, 0.05, 0.13};
  s.fills = {{0, {0, 0, 0.02}, {0.04, 0.04, 0.12}, 500, {0.05, -0.02, -0.3}}};
  s.seed = 11;
  return s;
}

// 1,200 spheres, enough for several sweep chunks, overlapping from the first step: many pairs
// cross chunk boundaries, and a chunk's cross pairs may be evaluated by another chunk's thread.
Scene JostlingPacking() {
  Scene s = PouredBox();
  s.fills.clear();
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

bool SameState(const Particles& a, const Particles& b) {
  if (a.Size() != b.Size()) return false;
  for (size_t i = 0; i < a.Size(); ++i)
    if (!(a.id[i] == b.id[i] && a.position_m[i] == b.position_m[i] &&
          a.velocity_m_s[i] == b.velocity_m_s[i] &&
          a.angular_velocity_rad_s[i] == b.angular_velocity_rad_s[i]))
      return false;
  return true;
}

}  // namespace

TEST_CASE("a poured packing is bit-identical with 1 and 2 threads", "[unit][physics]") {
  const Scene scene = PouredBox();
  Particles result[2];
  size_t contacts[2];
  for (const int threads : {1, 2}) {
    Simulation sim(scene, {.threads = threads});
    std::string err;
    const bool initialized = sim.Initialize(&err);
    INFO(err);
    REQUIRE(initialized);
    const RunSummary run = sim.Run(0.25);
    INFO(run.BriefReport());
    REQUIRE(run.ok());
    REQUIRE(run.neighbour_rebuilds > 20);  // rebuilds and particle reordering happened
    result[threads - 1] = sim.particles();
    contacts[threads - 1] = sim.ActiveContacts();
  }
  const Particles& a = result[0];
  const Particles& b = result[1];
  REQUIRE(a.Size() == 500);
  REQUIRE(b.Size() == a.Size());
  CHECK(contacts[0] > 500);  // a settled, touching packing
  CHECK(contacts[0] == contacts[1]);
  size_t differing = 0;
  for (size_t i = 0; i < a.Size(); ++i) {
    const bool same = a.id[i] == b.id[i] && a.position_m[i] == b.position_m[i] &&
                      a.velocity_m_s[i] == b.velocity_m_s[i] &&
                      a.angular_velocity_rad_s[i] == b.angular_velocity_rad_s[i];
    if (!same) ++differing;
  }
  CHECK(differing == 0);
}

TEST_CASE("a dense, jostling packing is bit-identical with 1 and 3 threads", "[unit][physics]") {
  const Scene s = JostlingPacking();
  Particles result[2];
  int run_index = 0;
  for (const int threads : {1, 3}) {
    Simulation sim(s, {.threads = threads});
    std::string err;
    const bool initialized = sim.Initialize(&err);
    INFO(err);
    REQUIRE(initialized);
    const RunSummary run = sim.Run(0.02);
    INFO(run.BriefReport());
    REQUIRE(run.ok());
    CHECK(sim.ActiveContacts() > 300);  // still a touching packing
    result[run_index++] = sim.particles();
  }
  CHECK(result[0].Size() == 1200);
  CHECK(SameState(result[0], result[1]));
}

TEST_CASE("the balance probe sweeps N chunks on one thread with the same result", "[unit][physics]") {
  // Simulation::Options::balance_probe_chunks: chunks run one after another, the last first, so
  // each evaluates its own cross pairs; the result is that of any thread count, and the balance
  // lies in (0, 1] (1 only for perfectly even chunks).
  const Scene s = JostlingPacking();
  Particles result[2];
  RunSummary runs[2];
  for (const int probe : {0, 4}) {
    Simulation sim(s, {.threads = 1, .balance_probe_chunks = probe});
    std::string err;
    REQUIRE(sim.Initialize(&err));
    runs[probe > 0] = sim.Run(0.02);
    REQUIRE(runs[probe > 0].ok());
    result[probe > 0] = sim.particles();
  }
  CHECK(SameState(result[0], result[1]));
  CHECK(runs[0].sweep_balance.passes == 0);
  const SweepBalance& b = runs[1].sweep_balance;
  CHECK(b.passes == runs[1].steps);
  CHECK(b.chunks == 4);
  CHECK(b.chunk_cpu_s > 0);
  CHECK(b.Efficiency() > 0);
  CHECK(b.Efficiency() <= 1.0);
  CHECK(b.CrossPairShare() > 0);  // 4 slabs of a 12-layer packing share boundary pairs
  CHECK(b.CrossPairShare() < 0.5);
}
