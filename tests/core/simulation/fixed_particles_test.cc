#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>

#include "core/math/random.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

Scene TwoSpheres(bool fix_lower) {
  Scene s;
  s.materials = {{"m", 1e7, 0.25, 1000}};
  s.species = {{"a", 0, {}}};
  s.species[0].size.diameter_m = 0.01;
  s.pair_parameters = {PairParameters{}};
  s.domain_min_m = {-1, -1, -1};
  s.domain_max_m = {1, 1, 1};
  ParticleSpec lower{0, {0, 0, 0}, {}, {}, 0};
  lower.fixed = fix_lower;
  s.particles = {lower, {0, {0.001, 0, 0.0105}, {}, {}, 0}};
  return s;
}

}  // namespace

TEST_CASE("a fixed sphere carries another without moving", "[unit]") {
  Simulation sim(TwoSpheres(true), {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(0.3).ok());
  const Particles& p = sim.particles();
  const size_t lower = p.id[0] < p.id[1] ? 0 : 1;
  CHECK(p.position_m[lower].x == 0);
  CHECK(p.position_m[lower].y == 0);
  CHECK(p.position_m[lower].z == 0);
  // The upper sphere rolled off the (off-centre) fixed one and fell below it.
  CHECK(p.position_m[1 - lower].z < -0.05);
  // A fixed sphere (infinite inertia) adds no kinetic energy, and no NaN.
  const size_t upper = 1 - lower;
  CHECK(sim.KineticEnergy() == Approx(p.FreeKineticEnergy(upper)).epsilon(1e-12));
}

TEST_CASE("fixed clumps are refused with the field name", "[unit]") {
  Scene s = TwoSpheres(true);
  s.species[0].clump_shape = {{{-0.5, 0, 0}, 1.0}, {{0.5, 0, 0}, 1.0}};
  std::string err;
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("particles[0].fixed"));
}

namespace {

// A glued base (a grid of fixed spheres lifted at random by up to half a radius, as
// objectives/common/glued_base.cc builds it) under a lattice of moving spheres thrown at it. The
// moving spheres are listed first, so without reordering both treatments keep the same slot order.
Scene PileOnFixedBase() {
  Scene s;
  s.materials = {{"grain", 1e7, 0.25, 2500}};
  s.species = {{"grain", 0, {}}};
  s.species[0].size.diameter_m = 0.004;
  PairParameters pair{0.5, 0.1, 0.5, 0};
  s.pair_parameters = {pair};
  s.rolling.name = "epsd";
  const double d = 0.004, r = 0.5 * d;
  s.walls = BoxInnerFaces("box", {0, 0, 0}, {0.07, 0.07, 0.1}, 0, /*open_top=*/true);
  s.domain_min_m = {-0.01, -0.01, -0.01};
  s.domain_max_m = {0.08, 0.08, 0.11};
  Rng rng(5);
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        const Vec3 v{rng.Uniform() - 0.5, rng.Uniform() - 0.5, rng.Uniform() - 1};
        s.particles.push_back({0, {0.02 + 1.1 * d * x, 0.02 + 1.1 * d * y, 0.015 + 1.1 * d * z},
                               0.3 * v, 20.0 * v, d, {}});
      }
  for (int y = 0; y < 17; ++y)
    for (int x = 0; x < 17; ++x) {
      ParticleSpec base{0, {0.003 + d * x, 0.003 + d * y, 0.001 + r * (1 + 0.5 * rng.Uniform())},
                        {}, {}, d, {}};
      base.fixed = true;  // 1 mm clear of the floor: the base never touches a wall
      s.particles.push_back(base);
    }
  return s;
}

// The base alone (289 fixed spheres) under a feed's stream.
Scene StreamOnFixedBase() {
  Scene s = PileOnFixedBase();
  s.particles.erase(s.particles.begin(), s.particles.begin() + 192);
  FactorySpec feed;
  feed.name = "feed";
  feed.region = InsertionRegion::Cylinder({0.035, 0.035, 0}, 0.008, 0.04, 0.07);
  feed.species = {0};
  feed.mass_fractions = {1};
  feed.mass_rate_kg_s = 0.05;
  s.factories = {feed};
  return s;
}

}  // namespace

TEST_CASE("fixed-fixed pairs are not listed; every pair with a moving sphere is", "[unit]") {
  // The fixed spheres come first in the scene: Initialize must move them after the moving ones.
  Scene scene = PileOnFixedBase();
  std::rotate(scene.particles.begin(), scene.particles.begin() + 192, scene.particles.end());
  Simulation sim(scene, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));  // the list of the initial positions
  const Particles& p = sim.particles();
  const NeighbourList& list = sim.neighbours();
  REQUIRE(list.FirstFixed() == 192);  // the moving spheres, all before the fixed ones
  for (size_t i = 0; i < p.Size(); ++i) CHECK(p.IsFixed(i) == (i >= list.FirstFixed()));
  const double skin = NeighbourSkin(sim.scene());
  size_t expected = 0, fixed_fixed_in_reach = 0;
  for (uint32_t i = 0; i < p.Size(); ++i)
    for (uint32_t j = i + 1; j < p.Size(); ++j) {
      const double reach = p.radius_m[i] + p.radius_m[j] + skin;
      if (Norm2(p.position_m[i] - p.position_m[j]) >= reach * reach) continue;
      if (p.IsFixed(i) && p.IsFixed(j)) {
        ++fixed_fixed_in_reach;
        continue;
      }
      ++expected;
      CHECK(list.Find(i, j) >= 0);
    }
  CHECK(fixed_fixed_in_reach > 500);  // the base's own pairs, which the list would hold
  CHECK(list.PairCount() == expected);
  for (uint32_t i = list.FirstFixed(); i < p.Size(); ++i) CHECK(list.RowBegin(i) == list.RowEnd(i));
}

TEST_CASE("a pile on a fixed base moves bit-identically with fixed pairs excluded or not",
          "[unit][physics]") {
  // The moving spheres' contacts with the base are the same pairs, evaluated by the same code
  // and summed in the same order; only the base's own pairs, force and integration are dropped.
  const Scene scene = PileOnFixedBase();
  auto run = [&](bool exclude, int threads) {
    Simulation sim(scene,
                   {.threads = threads, .reorder_every_rebuilds = 0, .exclude_fixed_pairs = exclude});
    std::string err;
    REQUIRE(sim.Initialize(&err));
    std::vector<Vec3> force_history;  // force on every moving sphere, every 20 steps
    const Simulation::Observer record{20, [&](const Simulation& s) {
      for (size_t i = 0; i < 192; ++i) force_history.push_back(s.particles().force_N[i]);
      return true;
    }};
    const RunSummary summary = sim.Run(0.15, record);
    INFO(summary.BriefReport());
    REQUIRE(summary.ok());
    REQUIRE(summary.neighbour_rebuilds > 10);
    return std::make_tuple(sim.particles(), force_history, sim.ActiveContacts(), sim.WallLoads(),
                           sim.neighbours().PairCount());
  };
  const auto [a, fa, ca, wa, pairs_a] = run(false, 1);
  for (const int threads : {1, 2}) {
    const auto [b, fb, cb, wb, pairs_b] = run(true, threads);
    INFO(threads << " threads");
    REQUIRE(b.Size() == a.Size());
    CHECK(pairs_b < pairs_a);  // the base's own pairs are gone
    CHECK(b.id == a.id);
    CHECK(b.position_m == a.position_m);
    CHECK(b.velocity_m_s == a.velocity_m_s);
    CHECK(b.angular_velocity_rad_s == a.angular_velocity_rad_s);
    REQUIRE(fb.size() == fa.size());
    CHECK(fb == fa);
    CHECK(cb == ca);
    REQUIRE(wb.size() == wa.size());
    for (size_t w = 0; w < wa.size(); ++w) CHECK(wb[w].force_N == wa[w].force_N);
  }
  size_t on_base = 0;  // the pile does rest on the base (and the base has not moved)
  for (size_t i = 0; i < 192; ++i) on_base += a.position_m[i].z > 0.004 && a.position_m[i].z < 0.02;
  CHECK(on_base > 50);
  const Scene initial = PileOnFixedBase();
  for (size_t i = 192; i < a.Size(); ++i) CHECK(a.position_m[i] == initial.particles[i].position_m);
}

TEST_CASE("a stream poured onto a fixed base is bit-identical with 1 and 2 threads", "[unit]") {
  // Factory newcomers are appended after the fixed spheres and must join the moving part; the
  // periodic spatial re-sort keeps the fixed spheres last.
  const Scene s = StreamOnFixedBase();
  Particles result[2];
  for (const int threads : {1, 2}) {
    Simulation sim(s, {.threads = threads});
    std::string err;
    REQUIRE(sim.Initialize(&err));
    const RunSummary summary = sim.Run(0.3);
    INFO(summary.BriefReport());
    REQUIRE(summary.ok());
    REQUIRE(summary.neighbour_rebuilds > 40);  // several re-sorts among them
    const Particles& p = sim.particles();
    REQUIRE(sim.neighbours().FirstFixed() == p.Size() - 289);
    for (size_t i = 0; i < p.Size(); ++i) CHECK(p.IsFixed(i) == (i >= p.Size() - 289));
    CHECK(sim.ActiveContacts() > 100);
    result[threads - 1] = p;
  }
  REQUIRE(result[0].Size() > 289 + 50);
  CHECK(result[0].id == result[1].id);
  CHECK(result[0].position_m == result[1].position_m);
  CHECK(result[0].velocity_m_s == result[1].velocity_m_s);
  CHECK(result[0].angular_velocity_rad_s == result[1].angular_velocity_rad_s);
}

TEST_CASE("a run counts the particles its rebuilds searched: one step at a time as at once",
          "[unit]") {
  // RunSummary::rebuild_search sums NeighbourList::LastMovers and FirstFixed over the rebuilds
  // of the run's steps. Runs of one step each read them off the list after each rebuild; their
  // sums are one long run's (whose kicks join across steps: the state must agree bit for bit).
  const Scene s = StreamOnFixedBase();
  Simulation whole(s, {.threads = 1}), stepped(s, {.threads = 1});
  std::string err;
  REQUIRE(whole.Initialize(&err));
  REQUIRE(stepped.Initialize(&err));
  const int steps = 4000;
  const RunSummary run = whole.Run(steps * whole.timestep_s());
  REQUIRE(run.ok());
  REQUIRE(run.steps == steps);
  uint64_t searched = 0, moving = 0, rebuilds = 0;
  for (int k = 0; k < steps; ++k) {
    const RunSummary one = stepped.Run(stepped.timestep_s());
    REQUIRE(one.ok());
    REQUIRE(one.neighbour_rebuilds <= 1);
    if (one.neighbour_rebuilds == 0) {
      CHECK(one.rebuild_search.moving == 0);
      continue;
    }
    ++rebuilds;
    CHECK(one.rebuild_search.searched == stepped.neighbours().LastMovers());
    CHECK(one.rebuild_search.moving == stepped.neighbours().FirstFixed());
    searched += one.rebuild_search.searched, moving += one.rebuild_search.moving;
  }
  REQUIRE(rebuilds == run.neighbour_rebuilds);
  REQUIRE(rebuilds > 20);
  CHECK(run.rebuild_search.searched == searched);
  CHECK(run.rebuild_search.moving == moving);
  CHECK(searched < moving);  // some rebuilds were incremental
  CHECK(whole.particles().position_m == stepped.particles().position_m);
  CHECK(whole.particles().velocity_m_s == stepped.particles().velocity_m_s);
}
