#include "objectives/metrics/segregation_floor.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "objectives/metrics/heap_segregation.h"
#include "objectives/metrics/synthetic_heap.h"

using namespace demcal::objectives;
using demcal::objectives::testing::MakeHeap;
using demcal::objectives::testing::RandomSpecies;
using demcal::objectives::testing::SpeciesRule;
using demcal::objectives::testing::SyntheticHeap;

namespace {

struct Measured {
  HeapSegregationAnalysis analysis;
  HeapFloor floor;
};

Measured Measure(const Snapshot& snap, const SyntheticHeap& heap, uint64_t seed,
                 int shuffles = 100) {
  std::string error;
  SegregationOptions options;
  options.random.seed = seed;
  auto analysis = AnalyseSegregationHeap(snap, {}, 3, options,
                                         HeapExtent{0.0, heap.width_m, 0.0, heap.height_m}, &error);
  INFO(error);
  REQUIRE(analysis);
  SegregationFloorOptions floor_options;
  floor_options.shuffles = shuffles;
  floor_options.seed = seed + 1000;
  auto floor = RandomMixtureFloor(analysis->grid, snap, analysis->indices, floor_options, &error);
  INFO(error);
  REQUIRE(floor);
  return {std::move(*analysis), std::move(*floor)};
}

bool Within(double value, const IndexFloor& f) {
  return f.s_n_defined && value >= f.s_n_low && value <= f.s_n_high;
}

}  // namespace

TEST_CASE("a random mixture reads as within its noise floor", "[unit]") {
  // A heap whose species are drawn at random is itself a random mixture: its S_n must fall in
  // the 95 % band of the shuffled heaps about 95 % of the time. Ten independent heaps: at least
  // 8 inside per index (P(fewer) < 2 % for a 95 % band). For a well-populated species the
  // shuffled S_n averages 1 (Eq. 7), up to the finite-population factor sqrt(1 − 1/21) of
  // sampling without replacement.
  const SyntheticHeap heap;
  int inside_ep_whole = 0, inside_ep_mass = 0, inside_taed_front = 0;
  for (int seed = 1; seed <= 10; ++seed) {
    const Measured m = Measure(MakeHeap(heap, 6000, seed, RandomSpecies(0.3, 0.05)), heap, seed);
    inside_ep_whole +=
        Within(m.analysis.indices.whole.species[2].number.s_n, m.floor.whole.species[2].number);
    inside_ep_mass +=
        Within(m.analysis.indices.whole.species[2].mass.s_n, m.floor.whole.species[2].mass);
    inside_taed_front +=
        Within(m.analysis.indices.front.species[1].number.s_n, m.floor.front.species[1].number);
    const IndexFloor& bp = m.floor.whole.species[0].number;
    CHECK(bp.shuffles_used == 100);
    CHECK(bp.s_n_mean == Approx(1.0).margin(0.12));
    CHECK(bp.s_n_low < bp.s_n_mean);
    CHECK(bp.s_n_high > bp.s_n_mean);
    CHECK(m.floor.layers.size() == 8);
    CHECK(m.floor.grains_shuffled == 6000 - m.analysis.counts.outside_count);
  }
  CHECK(inside_ep_whole >= 8);
  CHECK(inside_ep_mass >= 8);
  CHECK(inside_taed_front >= 8);
}

TEST_CASE("a fully segregated heap lies far outside its noise floor", "[unit]") {
  // EP only in the core of the heap (|x − centre| < width/8), BP elsewhere with some TAED.
  const SyntheticHeap heap;
  const SpeciesRule core = [&](const demcal::core::Vec3& p, demcal::core::Rng& rng) {
    if (std::abs(p.x - heap.width_m / 2) < heap.width_m / 8) return 2;
    return rng.Uniform() < 0.2 ? 1 : 0;
  };
  const Measured m = Measure(MakeHeap(heap, 6000, 3, core), heap, 3);
  for (const auto* region : {&m.floor.whole, &m.floor.front, &m.floor.back}) {
    const auto& measured = region == &m.floor.whole   ? m.analysis.indices.whole
                           : region == &m.floor.front ? m.analysis.indices.front
                                                      : m.analysis.indices.back;
    INFO(measured.range.name);
    const IndexFloor& ep = region->species[2].mass;
    REQUIRE(ep.s_n_defined);
    CHECK(measured.species[2].mass.s_n > 3 * ep.s_n_high);
    CHECK(measured.species[2].mass.cov_m > 3 * ep.cov_high);
  }
}

TEST_CASE("the noise floor widens as a species gets rarer", "[unit]") {
  // The point: at coarse fidelity a handful of EP grains gives a wide random band.
  const SyntheticHeap heap;
  const Measured many = Measure(MakeHeap(heap, 6000, 4, RandomSpecies(0.1, 0.1)), heap, 4);
  const Measured few = Measure(MakeHeap(heap, 6000, 4, RandomSpecies(0.1, 0.004)), heap, 4);
  const IndexFloor& a = many.floor.whole.species[2].number;
  const IndexFloor& b = few.floor.whole.species[2].number;
  CHECK(b.cov_high - b.cov_low > 3 * (a.cov_high - a.cov_low));
  CHECK(b.cov_mean > 3 * a.cov_mean);
}

TEST_CASE("the noise floor is deterministic from its seed and checks its options", "[unit]") {
  const SyntheticHeap heap;
  const Snapshot snap = MakeHeap(heap, 2000, 5, RandomSpecies(0.2, 0.05));
  const Measured a = Measure(snap, heap, 5, 30), b = Measure(snap, heap, 5, 30);
  CHECK(a.floor.whole.species[2].mass.s_n_high == b.floor.whole.species[2].mass.s_n_high);
  std::string error;
  SegregationFloorOptions bad;
  bad.shuffles = 5;
  CHECK_FALSE(RandomMixtureFloor(a.analysis.grid, snap, a.analysis.indices, bad, &error));
  CHECK(error.find("shuffles") != std::string::npos);
  bad = {};
  bad.band = 1.0;
  CHECK_FALSE(RandomMixtureFloor(a.analysis.grid, snap, a.analysis.indices, bad, &error));
  CHECK(error.find("band") != std::string::npos);
  CHECK_FALSE(RandomMixtureFloor(a.analysis.grid, Snapshot{}, a.analysis.indices, {}, &error));
  CHECK(error.find("no grain") != std::string::npos);
}
