#include "objectives/metrics/segregation_index.h"

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

HeapSegregation Analyse(const Snapshot& snap, const SyntheticHeap& heap, uint64_t seed) {
  std::string error;
  const auto grid = HeapBinGrid::Create({}, {0.0, heap.width_m, 0.0, heap.height_m}, &error);
  REQUIRE(grid);
  const auto counts = CountGrains(*grid, snap, 3, &error);
  REQUIRE(counts);
  SegregationOptions options;
  options.random.seed = seed;
  const auto result = AnalyseHeap(*counts, MeanGrainVolumes(snap, 3), options, &error);
  INFO(error);
  REQUIRE(result);
  return *result;
}

struct MeanAndSpread {
  double mean = 0, std_dev = 0;
};
MeanAndSpread Summarise(const std::vector<double>& values) {
  MeanAndSpread m;
  for (double v : values) m.mean += v / values.size();
  for (double v : values) m.std_dev += (v - m.mean) * (v - m.mean) / (values.size() - 1);
  m.std_dev = std::sqrt(m.std_dev);
  return m;
}

}  // namespace

TEST_CASE("a perfectly random mixture has S_n = 1 within its sampling noise", "[unit]") {
  // Eq. 7: S_n = CoV_m/CoV_r is 1 on average for a random mixture. Identical grains, so the
  // mass fractions are the number fractions and Eq. 6 holds exactly. The spread of S_n over
  // seeds is the noise of CoV_m (about 1/sqrt(2·20) for 21 bins); the mean over K seeds must
  // lie within 3 standard errors of 1.
  const SyntheticHeap heap;
  const int seeds = 16;
  std::vector<double> whole_number, whole_mass, front_number;
  for (int seed = 1; seed <= seeds; ++seed) {
    const Snapshot snap = MakeHeap(heap, 12000, seed, RandomSpecies(0.3, 0.08));
    const HeapSegregation result = Analyse(snap, heap, 100 + seed);
    REQUIRE(result.whole.species[2].number.defined);
    whole_number.push_back(result.whole.species[2].number.s_n);
    whole_mass.push_back(result.whole.species[1].mass.s_n);
    front_number.push_back(result.front.species[1].number.s_n);
    // A front layer holds 1/8 of the grains of a whole-heap bin, so its random reference is
    // about sqrt(8) larger (the paper: CoV_r 0.50 front vs 0.21 whole heap).
    CHECK(result.front.species[1].mass.cov_r / result.whole.species[1].mass.cov_r ==
          Approx(std::sqrt(8.0)).epsilon(0.15));
  }
  for (const auto& series : {whole_number, whole_mass, front_number}) {
    const MeanAndSpread s = Summarise(series);
    CHECK(s.std_dev == Approx(1 / std::sqrt(40.0)).epsilon(0.5));
    CHECK(std::abs(s.mean - 1) < 3 * s.std_dev / std::sqrt(seeds));
  }
}

TEST_CASE("a fully segregated heap has S_n much larger than 1", "[unit]") {
  // Species sorted by height (EP low, TAED high) and by x (TAED left): concentrations far
  // outside the random-mixture spread.
  const SyntheticHeap heap;
  const SpeciesRule sorted = [&](const demcal::core::Vec3& p, demcal::core::Rng&) {
    if (p.z < 0.1 * heap.height_m) return 2;
    return p.x < 0.3 * heap.width_m ? 1 : 0;
  };
  const HeapSegregation result = Analyse(MakeHeap(heap, 12000, 9, sorted), heap, 1);
  for (int species : {1, 2}) {
    INFO("species " << species);
    CHECK(result.whole.species[species].mass.s_n > 10);
    CHECK(result.whole.species[species].number.s_n > 10);
    CHECK(result.front.species[species].mass.s_n > 3);
  }
}

TEST_CASE("per-layer indices follow a segregation near the walls", "[unit]") {
  // Fig. 12: the front and back layers more segregated than the middle. EP sits only in the
  // bottom rows of the outer layers and is spread at random in the middle layers.
  const SyntheticHeap heap;
  const SpeciesRule walls = [&](const demcal::core::Vec3& p, demcal::core::Rng& rng) {
    const bool outer = p.y < 0.002 || p.y > heap.depth_m - 0.002;
    if (outer) return p.z < 0.15 * heap.height_m ? 2 : 0;
    return rng.Uniform() < 0.1 ? 2 : 0;
  };
  const HeapSegregation result = Analyse(MakeHeap(heap, 16000, 4, walls), heap, 2);
  REQUIRE(result.layers.size() == 8);
  CHECK(result.layers[0].range.name == "layer 1");
  const double middle = result.layers[4].species[2].mass.cov_m;
  CHECK(result.layers[0].species[2].mass.cov_m > 3 * middle);
  CHECK(result.layers[7].species[2].mass.cov_m > 3 * middle);
  CHECK(result.front.species[2].mass.cov_m == result.layers[0].species[2].mass.cov_m);
}

TEST_CASE("a species absent from a region has no index and no NaN", "[unit]") {
  const SyntheticHeap heap;
  const Snapshot snap = MakeHeap(heap, 3000, 5, RandomSpecies(0.2, 0.0));  // no species 2
  const HeapSegregation result = Analyse(snap, heap, 3);
  const SegregationIndex& ep = result.whole.species[2].mass;
  CHECK_FALSE(ep.defined);
  CHECK(ep.s_n == 0);
  CHECK_FALSE(ep.note.empty());
  CHECK(result.whole.species[1].mass.defined);
  CHECK(std::isfinite(result.whole.species[1].mass.s_n));
  std::string error;
  const auto grid = HeapBinGrid::Create({}, {0.0, heap.width_m, 0.0, heap.height_m}, &error);
  const auto counts = CountGrains(*grid, snap, 3, &error);
  CHECK_FALSE(AnalyseHeap(*counts, {1e-9}, {}, &error));
  CHECK(error.find("granule volume") != std::string::npos);
}

TEST_CASE("the one-call heap analysis equals the step-by-step one", "[unit]") {
  const SyntheticHeap heap;
  const Snapshot snap = MakeHeap(heap, 3000, 8, RandomSpecies(0.2, 0.1));
  std::string error;
  SegregationOptions options;
  options.random.seed = 4;
  const auto whole = AnalyseSegregationHeap(
      snap, {}, 3, options, HeapExtent{0.0, heap.width_m, 0.0, heap.height_m}, &error);
  REQUIRE(whole);
  CHECK(whole->grid.face_bin_count() == 21);
  const HeapSegregation steps = Analyse(snap, heap, 4);
  CHECK(whole->indices.whole.species[1].mass.s_n == steps.whole.species[1].mass.s_n);
  CHECK(whole->indices.layers.size() == 8);
  CHECK(AnalyseSegregationHeap(snap, {}, 3, options, std::nullopt, &error));
  CHECK_FALSE(AnalyseSegregationHeap(Snapshot{}, {}, 3, options, std::nullopt, &error));
  CHECK(error.find("no grains") != std::string::npos);
}
