#include "experiments/segregation/segregation_result.h"

#include <catch2/catch.hpp>

#include "objectives/metrics/synthetic_heap.h"

using namespace demcal;
using objectives::testing::MakeHeap;
using objectives::testing::RandomSpecies;
using objectives::testing::SyntheticHeap;

namespace {

// A run that "settled" onto a synthetic random heap, analysed with its noise floor.
objectives::SegregationRun SyntheticRun(uint64_t seed) {
  const SyntheticHeap heap;
  objectives::SegregationRun run;
  run.seed = seed;
  run.funnel_emptied = true;
  run.heap = MakeHeap(heap, 4000, seed, RandomSpecies(0.2, 0.05));
  objectives::SegregationOptions options;
  options.random.seed = seed;
  run.analysis = objectives::AnalyseSegregationHeap(
      run.heap, {}, 3, options, objectives::HeapExtent{0.0, heap.width_m, 0.0, heap.height_m},
      nullptr);
  REQUIRE(run.analysis);
  objectives::SegregationFloorOptions floor;
  floor.shuffles = 40;
  run.floor = objectives::RandomMixtureFloor(run.analysis->grid, run.heap, run.analysis->indices,
                                             floor, nullptr);
  REQUIRE(run.floor);
  return run;
}

}  // namespace

TEST_CASE("segregation result.json puts the noise floor beside every S_n", "[unit]") {
  objectives::SegregationSettings settings;
  settings.feed.components = {{2, 1.0}};
  const std::vector<objectives::SegregationRun> runs = {SyntheticRun(1), SyntheticRun(2)};
  const workflow::SegregationResult result =
      workflow::SummariseSegregation(settings, {"BP", "TAED", "EP"}, runs);
  const auto json = workflow::SegregationResultJson(result);
  REQUIRE(json["replicates_ok"] == 2);
  CHECK(json["noise_floor"]["shuffles"] == 200);  // the settings' default, not the test's 40
  const auto& ep = json["species"][2];
  for (const char* region : {"2d_front", "2d_back", "3d"}) {
    INFO(region);
    const auto& floor = ep[std::string("s_n_") + region + "_floor"];
    REQUIRE(floor["n"] == 2);
    CHECK(floor["low"].get<double>() < floor["mean"].get<double>());
    CHECK(floor["mean"].get<double>() < floor["high"].get<double>());
    CHECK(ep[std::string("cov_") + region + "_floor"]["n"] == 2);
    CHECK(ep.contains(std::string("s_n_") + region));  // the existing keys stay
  }
  const double mean = (runs[0].floor->whole.species[2].mass.s_n_high +
                       runs[1].floor->whole.species[2].mass.s_n_high) /
                      2;
  CHECK(ep["s_n_3d_floor"]["high"].get<double>() == Approx(mean));
  CHECK(ep["cov_per_layer_3d"][0]["floor"]["n"] == 2);
  CHECK(json["runs"][0]["heap_grains_per_species"].size() == 3);
}

TEST_CASE("the typed segregation result holds what result.json is written from", "[unit]") {
  objectives::SegregationSettings settings;
  settings.feed.components = {{2, 1.0}};
  const std::vector<objectives::SegregationRun> runs = {SyntheticRun(1), SyntheticRun(2)};
  const workflow::SegregationResult result =
      workflow::SummariseSegregation(settings, {"BP", "TAED", "EP"}, runs);
  const auto json = workflow::SegregationResultJson(result);
  CHECK(result.replicates_ok == 2);
  CHECK(result.runs.size() == 2);
  REQUIRE(result.species.size() == 3);
  const workflow::SegregationSpeciesResult& ep = result.species[2];
  CHECK(ep.species == "EP");
  REQUIRE(ep.Index("s_n_3d"));
  CHECK(ep.Index("s_n_3d")->n == 2);
  CHECK(ep.Index("s_n_3d")->mean == json["species"][2]["s_n_3d"]["mean"].get<double>());
  CHECK(ep.Index("s_n_3d")->sem == json["species"][2]["s_n_3d"]["sem"].get<double>());
  CHECK(ep.Index("no_such_index") == nullptr);
  REQUIRE(ep.Floor("s_n_3d_floor"));
  CHECK(ep.Floor("s_n_3d_floor")->high == json["species"][2]["s_n_3d_floor"]["high"].get<double>());
  CHECK(ep.Floor("cov_r_3d_floor") == nullptr);  // CoV_r has no floor of its own
  // The headline values name each species' indices.
  bool found = false;
  for (const workflow::NamedEstimate& v : result.Values())
    if (v.name == "EP.s_n_3d") found = v.value.mean == ep.Index("s_n_3d")->mean;
  CHECK(found);
}
