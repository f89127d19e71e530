// Periodic boundaries: minimum-image neighbours and contacts across the boundary.
#include <catch2/catch.hpp>

#include <set>

#include "core/math/random.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {
// 2 mm spheres in a 20 mm cube, no walls.
Scene SmallBox() {
  Scene s;
  s.materials = {{"m", 1e7, 0.25, 1000}};
  s.species = {{"a", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.002;
  s.pair_parameters = {PairParameters{}};
  s.domain_min_m = {0, 0, 0};
  s.domain_max_m = {0.02, 0.02, 0.02};
  return s;
}
}  // namespace

TEST_CASE("periodic neighbour list matches a minimum-image brute force", "[unit][periodic]") {
  const Vec3 lo{0, 0, 0}, hi{0.02, 0.015, 0.03};
  for (uint64_t seed : {1u, 2u, 3u}) {
    Rng rng(seed);
    std::vector<Vec3> x;
    std::vector<double> r;
    for (int i = 0; i < 400; ++i) {
      x.push_back({rng.Uniform(lo.x, hi.x), rng.Uniform(lo.y, hi.y), rng.Uniform(lo.z, hi.z)});
      r.push_back(rng.Uniform(0.0004, 0.0008));
    }
    PeriodicBox box{lo, {hi.x - lo.x, hi.y - lo.y, 0}};  // periodic in x and y only
    NeighbourList list;
    const double skin = 0.0003;
    list.Build({lo, hi, skin, 0.0008, box}, x, r);
    std::set<std::pair<uint32_t, uint32_t>> found, expected;
    for (uint32_t i = 0; i < x.size(); ++i)
      for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) found.insert({i, list.Partner(k)});
    for (uint32_t i = 0; i < x.size(); ++i)
      for (uint32_t j = i + 1; j < x.size(); ++j) {
        const double reach = r[i] + r[j] + skin;
        if (Norm2(box.MinimumImage(x[i] - x[j])) < reach * reach) expected.insert({i, j});
      }
    CHECK(found == expected);
    CHECK(found.size() == list.PairCount());
  }
}

TEST_CASE("two spheres touching across a periodic boundary repel through it", "[unit][periodic]") {
  Scene s = SmallBox();
  s.periodic = {true, false, false};
  s.gravity_m_s2 = {0, 0, 0};
  // Centres 1.9 mm apart through the x boundary (0.0009 and 0.019): overlap 0.1 mm.
  s.particles = {{0, {0.0009, 0.01, 0.01}, {}, {}, 0, {}}, {0, {0.019, 0.01, 0.01}, {}, {}, 0, {}}};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  // Through the boundary, sphere 0 (near x = 0) is pushed to +x and sphere 1 (near x = L) to −x.
  CHECK(sim.particles().force_N[0].x > 0);
  CHECK(sim.particles().force_N[1].x < 0);
  // After 5 ms they have separated across the boundary (they meet again mid-box at ~10 ms).
  REQUIRE(sim.Run(0.005).ok());
  const double v0 = sim.particles().velocity_m_s[0].x;
  CHECK(v0 > 0);
  CHECK(sim.particles().velocity_m_s[1].x == Approx(-v0).epsilon(1e-9));
  // Momentum is conserved and both stayed inside the periodic box.
  for (const Vec3& p : sim.particles().position_m) CHECK((p.x >= 0 && p.x < 0.02));
}

TEST_CASE("a sphere leaving through a periodic face re-enters on the other side", "[unit][periodic]") {
  Scene s = SmallBox();
  s.periodic = {false, true, false};
  s.gravity_m_s2 = {0, 0, 0};
  s.particles = {{0, {0.01, 0.019, 0.01}, {0, 1.0, 0}, {}, 0, {}}};
  Simulation sim(s, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  const RunSummary r = sim.Run(0.005);  // moves 5 mm: crosses y = 0.02 once
  REQUIRE(r.ok());
  CHECK(sim.particles().position_m[0].y == Approx(0.019 + sim.time_s() - 0.02).margin(1e-12));
}

TEST_CASE("periodic axes along gravity or too short are rejected", "[unit][periodic]") {
  Scene s = SmallBox();
  s.domain_max_m = {0.005, 0.02, 0.02};
  s.periodic = {false, false, true};
  std::string err;
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("periodic.z") && Catch::Contains("gravity"));
  s.periodic = {true, false, false};
  CHECK_FALSE(s.IsValid(&err));
  CHECK_THAT(err, Catch::Contains("periodic.x") && Catch::Contains("at least 3"));
}
