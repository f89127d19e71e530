// demcal-study/2 files (study_file.h): targets over experiments and conditions, per-condition
// and curve parameters, constraints and the clump-count loop; errors name the JSON path.
#include <catch2/catch.hpp>
#include <fstream>

#include "core/io/scratch_dir.h"
#include "workflow/calibration/study_file.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"

using namespace demcal::workflow;
using demcal::testing::ReadJson;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;
using nlohmann::json;

namespace {

json Example() {
  json j = ReadJson((RepoRoot() / "examples/calibrate_bp_two_targets.json").string());
  j["measurements"] = (RepoRoot() / "datasets/synthetic/bp_friction_twin/measurements.csv").string();
  for (json& t : j["targets"]) t["experiment_file"] = (RepoRoot() / "examples" / t["experiment_file"].get<std::string>()).string();
  for (json& t : j["candidate_targets"]) t["experiment_file"] = (RepoRoot() / "examples" / t["experiment_file"].get<std::string>()).string();
  return j;
}

std::string Load(const ScratchDir& dir, const json& j, StudyFile* out) {
  std::ofstream(dir.str("s.json")) << j.dump(2);
  std::string error;
  return LoadStudyFile(dir.str("s.json"), out, &error) ? "ok" : error;
}

}  // namespace

TEST_CASE("the two-target example: two experiments, synthetic targets, free candidate targets", "[unit][calibrate]") {
  StudyFile st;
  std::string error;
  REQUIRE(LoadStudyFile((RepoRoot() / "examples/calibrate_bp_two_targets.json").string(), &st, &error));
  REQUIRE(st.targets.size() == 2);
  CHECK(st.experiments.size() == 2);
  CHECK(st.targets[0].provenance == "synthetic");
  CHECK(st.targets[0].target.uncertainty == 1.0);
  CHECK(st.targets[1].experiment == 1);
  CHECK(st.candidate_targets.size() == 3);
  CHECK(st.options.optimiser == "ceres");
  CHECK(st.options.optimiser_options.batch_size == 4);
}

TEST_CASE("study/2: per-condition parameters, curves, constraints and the clump count", "[unit][calibrate]") {
  ScratchDir dir("study_v2");
  StudyFile st;
  json j = Example();
  j["parameters"] = json::parse(R"js([
    {"name": "mu_r", "property": "rolling_friction", "materials": ["BP", "BP"], "min": 0.05, "max": 0.5},
    {"name": "mu_s_funnel", "property": "sliding_friction", "materials": ["BP", "BP"], "min": 0.2, "max": 1,
     "when": {"test": "funnel"}},
    {"name": "gamma(w)", "property": "interfacial_energy_J_m2", "materials": ["BP", "BP"],
     "curve": {"covariate": "w", "form": "linear",
               "coefficients": [{"name": "g0", "min": 0, "max": 0.1}, {"name": "g1", "min": 0, "max": 0.1}]}}])js");
  j["constraints"] = json::parse(R"js([{"non_decreasing": ["g0", "g1"]}])js");
  j["clump_count"] = json::parse(R"({"species": "BP", "semi_axes": [1.5, 1, 1], "counts": [1, 2, 3]})");
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("field 'parameters[2].curve.covariate' 'w' cannot "
                                                "be read for target"));
  {  // the covariate as a number in every row: a column w in a copy of the table
    std::ifstream in(j["measurements"].get<std::string>());
    std::ofstream out(dir.str("table.csv"));
    std::string line;
    for (int n = 0; std::getline(in, line); ++n) out << line << (n == 0 ? ",w" : ",1") << "\n";
  }
  j["measurements"] = dir.str("table.csv");
  REQUIRE(Load(dir, j, &st) == "ok");
  REQUIRE(st.space.Size() == 4);
  CHECK(st.space.parameters[1].when.at("test") == "funnel");
  REQUIRE(st.space.curves.size() == 1);
  CHECK(st.space.curves[0].coefficients == std::vector<int>{2, 3});
  CHECK(st.space.non_decreasing == std::vector<std::vector<int>>{{2, 3}});
  CHECK(st.clump_count.counts == std::vector<int>{1, 2, 3});

  j["clump_count"]["counts"] = {1, 4294967297};
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("clump_count.counts[1]' = 4294967297 is outside"));
  j["clump_count"]["counts"] = {-4294967295, 2};
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("clump_count.counts[0]' = -4294967295 is outside"));
  j["clump_count"]["counts"] = {3, 2};
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("clump_count.counts") && Catch::Contains("ascending"));
  j.erase("clump_count");
  j["constraints"][0]["non_decreasing"] = {"g0", "nope"};
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("constraints[0].non_decreasing"));
  j.erase("constraints");
  j["parameters"][2]["curve"]["covariate"] = "test";
  CHECK_THAT(Load(dir, j, &st),
             Catch::Contains("gives 'test' a word, 'pseudo-2D heap', not a number"));
  j["parameters"][2]["curve"]["covariate"] = "w";
  j["parameters"][2]["curve"]["form"] = "linear_through_origin";
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("has 1 coefficients"));
}

TEST_CASE("study/2 errors name the target and the field", "[unit][calibrate]") {
  ScratchDir dir("study_v2_errors");
  StudyFile st;
  json j = Example();
  j["targets"][1]["observable"] = "angle_deg";  // the funnel has no repose angle
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("targets[1]") || Catch::Contains("BP"));
  j = Example();
  j["targets"][0]["measurement"]["conditions"]["test"] = "lifted cylinder";
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("no row with angle_deg of BP"));
  j = Example();
  j["targets"][0]["observable"] = "porosity";
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("targets[0].observable"));
  j = Example();
  j["targets"][1]["name"] = j["targets"][0]["name"];
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("used twice"));
  j = Example();
  j["parameters"][0]["materials"] = {"BP", "sugar"};
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("parameters[0].materials"));
}

TEST_CASE("study/2: optimiser.bracket_points is read, default 1, range named", "[unit][calibrate]") {
  ScratchDir dir("study_v2_bracket_points");
  StudyFile st;
  json j = Example();
  REQUIRE(Load(dir, j, &st) == "ok");
  CHECK(st.options.optimiser_options.bracket_points == 1);
  j["optimiser"]["bracket_points"] = 4;
  REQUIRE(Load(dir, j, &st) == "ok");
  CHECK(st.options.optimiser_options.bracket_points == 4);
  for (int bad : {0, 1025}) {
    j["optimiser"]["bracket_points"] = bad;
    const std::string error = Load(dir, j, &st);
    CHECK_THAT(error, Catch::Contains("bracket_points") && Catch::Contains("1024"));
  }
}

TEST_CASE("a key of the other study format is refused, not ignored", "[unit][calibrate]") {
  ScratchDir dir("study_mixed_formats");
  StudyFile st;
  json j = Example();
  j["measurement"] = json::object();
  CHECK_THAT(Load(dir, j, &st), Catch::EndsWith("s.json: field 'measurement' is a demcal-study/1 "
                                                "key, but this file is demcal-study/2, which does "
                                                "not read it"));
  j = Example();
  j["experiment_file"] = "aor.json";
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("'experiment_file' is a demcal-study/1 key"));
  j = ReadJson((RepoRoot() / "examples/calibrate_bp_rolling.json").string());
  REQUIRE(j["format"] == "demcal-study/1");
  j["targets"] = json::array();
  CHECK_THAT(Load(dir, j, &st), Catch::Contains("field 'targets' is a demcal-study/2 key, but this "
                                                "file is demcal-study/1"));
}

TEST_CASE("the one-angle example: one target, a candidate target in another experiment", "[unit][calibrate]") {
  StudyFile st;
  std::string error;
  REQUIRE(LoadStudyFile((RepoRoot() / "examples/calibrate_bp_one_angle.json").string(), &st, &error));
  CHECK(st.targets.size() == 1);
  REQUIRE(st.candidate_targets.size() == 3);
  CHECK(st.candidate_targets[0].experiment == 1);  // the funnel: runs of its own
  CHECK(st.space.Size() == 2);
}
