// `demcal calibrate` end to end on real poured heaps at the quick fidelity, with a budget of a
// few candidates: the outputs exist and agree with the journal, and a second run with a larger
// budget resumes from the journal instead of repeating the finished heaps; the typed front door
// (CalibrateStudy) returns what result.json holds.
#include "workflow/calibration/run_study.h"

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "outputs/exit_codes.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"
#include "core/io/scratch_dir.h"

using namespace demcal::workflow;
using demcal::testing::ReadFile;
using demcal::testing::ReadJson;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;

namespace {

int Lines(const std::string& path) {
  std::istringstream in(ReadFile(path));
  std::string line;
  int n = 0;
  while (std::getline(in, line)) ++n;
  return n;
}

}  // namespace

TEST_CASE("calibrate writes its outputs and resumes from the journal", "[dem][calibrate]") {
  ScratchDir dir("calibrate_e2e");
  nlohmann::json study = ReadJson((RepoRoot() / "examples/calibrate_bp_rolling.json").string());
  study["experiment_file"] = (RepoRoot() / "examples/aor_bp.json").string();
  study["measurement"]["dataset"] = (RepoRoot() / "datasets/alizadeh2018/measurements.csv").string();
  study["replicates"] = 1;
  std::ofstream(dir.str("study.json")) << study.dump(2);

  CalibrateOptions o{dir.str("study.json"), dir.str("out"), /*quick=*/true, /*max_evaluations=*/2, 0, true};
  std::ostringstream log;
  CHECK(RunCalibrate(o, log) == kExitRunFailed);  // two candidates cannot reach 40 deg: "budget"
  INFO(log.str());
  const nlohmann::json first = ReadJson(dir.str("out/result.json"));
  CHECK(first["termination"] == "budget");
  CHECK(first["replicates_run"] == 2);
  CHECK(first["provenance"]["fidelity"]["name"] == "quick");
  CHECK(first["provenance"]["targets"][0]["value"] == 40.0);
  CHECK(first["targets"][0]["measured"] == 40.0);
  CHECK(first["parameters"][0]["name"] == "mu_r_BP_BP");
  CHECK(Lines(dir.str("out/journal.jsonl")) == 1 + 2);       // header + one line per heap
  CHECK(Lines(dir.str("out/evaluations.csv")) == 1 + 2);     // header + one row per candidate
  const nlohmann::json params = ReadJson(dir.str("out/calibrated_params.json"));
  CHECK(params["format"] == "demcal-params/1");
  CHECK(params["interactions_pairs"][0]["materials"] == nlohmann::json({"BP", "BP"}));
  for (const char* svg : {"calibration.svg", "targets.svg", "convergence.svg", "profile_mu_r_BP_BP.svg"})
    CHECK(ReadFile(dir.str(std::string("out/") + svg)).find("<svg") != std::string::npos);
  const std::string deck = ReadFile(dir.str("out/calibrated_params.liggghts"));
  // demcal's cdt is not LIGGGHTS' cdt (docs/export.md): the include names the pair instead.
  CHECK(deck.find("# NOT EXPORTED: material pair BP–BP") != std::string::npos);
  CHECK(deck.find("coefficientRollingFriction") == std::string::npos);

  // The typed front door on the same study, into the same folder: every heap comes from the
  // journal, and the result carries what result.json holds.
  StudyFile parsed;
  std::string error;
  REQUIRE(LoadStudyFile(dir.str("study.json"), &parsed, &error));
  const CalibrationResult typed = CalibrateStudy(
      parsed, {.out_dir = dir.str("out"), .quick = true, .max_evaluations = 2, .quiet = true}, log);
  CHECK(typed.status == CalibrationStatus::kNotMatched);
  CHECK(ExitCodeOf(typed.status) == kExitRunFailed);
  CHECK(typed.summary.replicates_run == 0);
  CHECK(typed.summary.replicates_reused == 2);
  CHECK(demcal::calibrate::TerminationName(typed.termination) == first["termination"].get<std::string>());
  CHECK(typed.out_dir == dir.str("out"));
  REQUIRE(typed.parameters.size() == 1);
  CHECK(typed.parameters[0].name == "mu_r_BP_BP");
  CHECK(typed.parameters[0].value == first["parameters"][0]["value"].get<double>());
  REQUIRE(typed.targets.size() == 1);
  CHECK(typed.targets[0].measured == 40.0);
  CHECK(typed.targets[0].simulated == first["targets"][0]["simulated"].get<double>());
  CHECK(typed.targets[0].sem == first["targets"][0]["sem"].get<double>());
  CHECK(typed.targets[0].provenance == first["provenance"]["targets"][0]["provenance"]);

  o.max_evaluations = 3;
  RunCalibrate(o, log);
  const nlohmann::json second = ReadJson(dir.str("out/result.json"));
  CHECK(second["replicates_reused"] == 2);
  CHECK(second["replicates_run"] == 1);
  CHECK(Lines(dir.str("out/journal.jsonl")) == 1 + 3);
}
