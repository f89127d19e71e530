// The "segregation" section of an experiment file: the shipped example parses at both of its
// fidelities, and every rejected value is reported with its field's path.
#include "experiments/segregation/segregation_section.h"

#include <catch2/catch.hpp>
#include <functional>
#include <string>

#include "experiments/common/experiment_file.h"
#include "objectives/common/fidelity.h"
#include "workflow/test_paths.h"

namespace demcal::workflow {
namespace {

ExperimentFile Example() {
  ExperimentFile file;
  std::string error;
  const std::string path = (testing::RepoRoot() / "examples/segregation_paper.json").string();
  REQUIRE(LoadExperimentFile(path, &file, &error));
  return file;
}

// Parses the example's section with `edit` applied at the example's default fidelity.
std::string ErrorAfter(const std::function<void(nlohmann::json&)>& edit) {
  ExperimentFile file = Example();
  objectives::ApplyFidelity(file.fidelity, &file.model);
  nlohmann::json section = file.section;
  edit(section);
  objectives::SegregationSettings settings;
  std::string error;
  if (ParseSegregationSection(section, "s.json", file.model, &settings, &error)) return "";
  return error;
}

TEST_CASE("the segregation example parses at its default and quick fidelity", "[unit]") {
  const ExperimentFile file = Example();
  CHECK(file.experiment == "segregation");
  for (const objectives::Fidelity& f : {file.fidelity, file.quick_fidelity}) {
    core::Scene model = file.model;
    objectives::ApplyFidelity(f, &model);
    objectives::SegregationSettings s;
    std::string error;
    INFO(f.name);
    REQUIRE(ParseSegregationSection(file.section, file.source, model, &s, &error));
    CHECK(s.feed.mass_kg == Approx(0.03085));
    CHECK(s.feed.components.size() == 3);
    CHECK(s.depth_m == Approx(0.016));
    CHECK(s.bins.layers == 8);
    CHECK(s.TrackedSpecies() == model.SpeciesIndex("EP"));
  }
}

TEST_CASE("segregation section errors name the field", "[unit]") {
  CHECK(ErrorAfter([](nlohmann::json&) {}).empty());
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["width_m"] = -1; }),
             Catch::Contains("segregation.width_m"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["width_m"] = 0.01; }),
             Catch::Contains("segregation.width_m"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) {
               s["funnel"].erase("effective_orifice_diameter_m");
               s["funnel"]["orifice_diameter_m"] = 0.004;
             }),
             Catch::Contains("segregation.funnel.orifice_diameter_m"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["funnel"]["orifice_diameter_m"] = 0.014; }),
             Catch::Contains("segregation.funnel.effective_orifice_diameter_m"));
  // 2 mm + 0.5 · 4 mm = 4 mm < 3 · 4 mm at the file's size ×4: the funnel would jam.
  CHECK_THAT(
      ErrorAfter([](nlohmann::json& s) { s["funnel"]["effective_orifice_diameter_m"] = 0.002; }),
      Catch::Contains("segregation.funnel.effective_orifice_diameter_m"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["funnel"]["beverloo_k"] = 3; }),
             Catch::Contains("segregation.funnel.beverloo_k"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["funnel"]["spout"] = 1; }),
             Catch::Contains("segregation.funnel"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) {
               s["bins"]["row_bins"] = {6, 0};
             }),
             Catch::Contains("segregation.bins.row_bins[1]"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["bins"]["layers"] = 0; }),
             Catch::Contains("segregation.bins.layers"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["segregation_index"]["draw"] = "uniform"; }),
             Catch::Contains("segregation.segregation_index.draw"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["segregation_index"]["floor_shuffles"] = 5; }),
             Catch::Contains("segregation.segregation_index.floor_shuffles"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["segregation_index"]["floor_band"] = 1; }),
             Catch::Contains("segregation.segregation_index.floor_band"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["tracking"]["species"] = "salt"; }),
             Catch::Contains("segregation.tracking.species"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["tracking"]["start_fraction"] = 1; }),
             Catch::Contains("segregation.tracking.start_fraction"));
  CHECK_THAT(
      ErrorAfter([](nlohmann::json& s) { s["feed"]["components"][2]["mass_fraction"] = 0.5; }),
      Catch::Contains("segregation.feed.components"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s.erase("wall_material"); }),
             Catch::Contains("segregation.wall_material"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["wal_material"] = "perspex"; }),
             Catch::Contains("wal_material"));
  CHECK_THAT(ErrorAfter([](nlohmann::json& s) { s["funnel_material"] = "glass"; }),
             Catch::Contains("segregation.funnel_material"));
}

TEST_CASE("segregation funnel_material: absent, the funnel is of the wall material", "[unit]") {
  ExperimentFile file = Example();
  objectives::ApplyFidelity(file.fidelity, &file.model);
  nlohmann::json section = file.section;
  objectives::SegregationSettings s;
  std::string error;
  REQUIRE(ParseSegregationSection(section, "s.json", file.model, &s, &error));
  CHECK(s.FunnelMaterial() == s.wall_material);
  section["funnel_material"] = "EP";
  REQUIRE(ParseSegregationSection(section, "s.json", file.model, &s, &error));
  CHECK(s.FunnelMaterial() == file.model.MaterialIndex("EP"));
  CHECK(s.wall_material == file.model.MaterialIndex("perspex"));
}

TEST_CASE("segregation funnel: false pours from the feeder", "[unit]") {
  ExperimentFile file = Example();
  objectives::ApplyFidelity(file.fidelity, &file.model);
  nlohmann::json section = file.section;
  section["funnel"] = false;
  objectives::SegregationSettings s;
  std::string error;
  REQUIRE(ParseSegregationSection(section, "s.json", file.model, &s, &error));
  CHECK_FALSE(s.funnel.enabled);
}

}  // namespace
}  // namespace demcal::workflow
