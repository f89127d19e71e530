#include "workflow/calibration/study_file.h"

#include <catch2/catch.hpp>
#include <fstream>

#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"
#include "core/io/scratch_dir.h"

using namespace demcal::workflow;
using demcal::testing::ReadJson;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;
using nlohmann::json;

namespace {

// The example study with absolute paths, so a modified copy can live in a scratch directory.
json ExampleStudy() {
  json j = ReadJson((RepoRoot() / "examples/calibrate_bp_rolling.json").string());
  j["experiment_file"] = (RepoRoot() / "examples/aor_bp.json").string();
  j["measurement"]["dataset"] = (RepoRoot() / "datasets/alizadeh2018/measurements.csv").string();
  return j;
}

std::string Load(const ScratchDir& dir, const json& study, bool* ok) {
  const std::string path = dir.str("study.json");
  std::ofstream(path) << study.dump(2);
  StudyFile file;
  std::string error;
  *ok = LoadStudyFile(path, &file, &error);
  return error;
}

}  // namespace

TEST_CASE("the example study reads its measurement from the dataset", "[unit][calibrate]") {
  StudyFile study;
  std::string error;
  REQUIRE(LoadStudyFile((RepoRoot() / "examples/calibrate_bp_rolling.json").string(), &study, &error));
  CHECK(study.targets[0].target.value == 40.0);  // Table 1, BP
  CHECK(study.targets[0].target.uncertainty == 1.0);
  CHECK(study.targets[0].target.source.find("Table 1") != std::string::npos);
  REQUIRE(study.space.Size() == 1);
  CHECK(study.space.parameters[0].property == demcal::calibrate::PairProperty::kRollingFriction);
  CHECK(study.experiment().experiment == "aor");
}

TEST_CASE("study file errors name the file and the field", "[unit][calibrate]") {
  ScratchDir dir("study_errors");
  bool ok = true;
  json j = ExampleStudy();
  j["measurement"].erase("uncertainty_deg");
  CHECK(Load(dir, j, &ok).find("measurement.uncertainty_deg' required") != std::string::npos);
  CHECK_FALSE(ok);

  j = ExampleStudy();
  j["measurement"]["material"] = "sugar";
  CHECK(Load(dir, j, &ok).find("no row with angle_deg of sugar") != std::string::npos);

  j = ExampleStudy();
  j["parameters"][0]["materials"] = {"BP", "glass"};
  CHECK(Load(dir, j, &ok).find("parameters[0].materials") != std::string::npos);

  j = ExampleStudy();
  j["parameters"][0]["start"] = 2.0;
  CHECK(Load(dir, j, &ok).find("parameters[0].start") != std::string::npos);

  j = ExampleStudy();
  j["parameters"].push_back({{"name", "mu_s"}, {"property", "sliding_friction"},
                             {"materials", {"BP", "BP"}}, {"min", 0.1}, {"max", 1.0}});
  CHECK(Load(dir, j, &ok).find("optimiser.name: 'bracket' fits exactly one parameter") != std::string::npos);

  j = ExampleStudy();
  j["optimiser"]["name"] = "genetic";
  CHECK(Load(dir, j, &ok).find("optimiser.name") != std::string::npos);

  j = ExampleStudy();
  j["budget"] = 3;
  CHECK(Load(dir, j, &ok).find("budget") != std::string::npos);
  CHECK_FALSE(ok);
}
