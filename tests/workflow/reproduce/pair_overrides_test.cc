// segregation.pair_overrides: pair properties no stage calibrates (the EP–BP rolling friction,
// which Table 1 gives only per material) set on the heap's file in every scenario, said in its
// description, and refused where they name a material the file lacks or a species' own pair
// that stage 1 calibrates.
#include "workflow/reproduce/pair_overrides.h"

#include <catch2/catch.hpp>

#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/segregation_example.h"

namespace demcal::workflow {
namespace {

nlohmann::ordered_json Example() { return testing_support::SegregationExample(); }

WorkflowFile WithOverrides(std::vector<PairOverride> overrides) {
  WorkflowFile w;
  w.source = "flow.json";
  w.segregation.experiment_file = "examples/segregation_paper.json";
  w.species.push_back({});
  w.species.back().name = "EP";
  w.species.back().property = "rolling_friction";
  w.segregation.pair_overrides = std::move(overrides);
  return w;
}

}  // namespace

TEST_CASE("pair overrides set the pair in the heap's file and say so", "[unit]") {
  nlohmann::ordered_json e = Example();
  const double ep_ep = PairProperty(e, "EP", "EP", "rolling_friction", -1);
  const double bp_taed = PairProperty(e, "BP", "TAED", "sliding_friction", -1);
  std::string error;
  const WorkflowFile w = WithOverrides({{"EP", "BP", "rolling_friction", 0.25, "bracket"},
                                        {"TAED", "EP", "rolling_friction", 0.2, "bracket"}});
  REQUIRE(ApplyPairOverrides(w, &e, &error));
  CHECK(PairProperty(e, "BP", "EP", "rolling_friction", -1) == 0.25);
  CHECK(PairProperty(e, "EP", "TAED", "rolling_friction", -1) == 0.2);
  CHECK(PairProperty(e, "EP", "EP", "rolling_friction", -1) == ep_ep);  // untouched
  CHECK(PairProperty(e, "BP", "TAED", "sliding_friction", -1) == bp_taed);
  const std::string description = e["description"].get<std::string>();
  CHECK(description.find("rolling_friction EP-BP set to 0.25 by the workflow (bracket)") !=
        std::string::npos);
  ExperimentFile file;
  const bool parsed = ParseEditedExperiment(e, "copy.json", &file, &error);
  INFO(error);
  CHECK(parsed);
}

TEST_CASE("pair overrides refuse a material the file lacks and a calibrated species' own pair",
          "[unit]") {
  std::string error;
  nlohmann::ordered_json e = Example();
  const nlohmann::ordered_json unchanged = e;
  CHECK_FALSE(
      ApplyPairOverrides(WithOverrides({{"EP", "XX", "rolling_friction", 0.2, "n"}}), &e, &error));
  CHECK(error.find("flow.json: segregation.pair_overrides[0].materials: 'XX'") !=
        std::string::npos);
  CHECK(error.find("one of BP") != std::string::npos);
  CHECK_FALSE(ApplyPairOverrides(WithOverrides({{"BP", "EP", "rolling_friction", 0.2, "n"},
                                                {"EP", "EP", "rolling_friction", 0.2, "n"}}),
                                 &e, &error));
  CHECK(error.find("segregation.pair_overrides[1]") != std::string::npos);
  CHECK(error.find("stage 1 calibrates") != std::string::npos);
  CHECK(e == unchanged);  // nothing applied when one is refused
  // EP's own sliding friction is not what stage 1 calibrates here: it may be set.
  nlohmann::ordered_json f = unchanged;
  CHECK(
      ApplyPairOverrides(WithOverrides({{"EP", "EP", "sliding_friction", 0.4, "n"}}), &f, &error));
}

}  // namespace demcal::workflow
