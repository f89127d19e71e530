// The typed calibration result (calibration_result.h) from an optimiser summary: the values
// result.json writes, with "no value" as NaN where result.json writes null.
#include "workflow/calibration/calibration_result.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "outputs/exit_codes.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
namespace calibrate = demcal::calibrate;
using demcal::testing::RepoRoot;

namespace {

StudyFile ExampleStudy() {
  StudyFile study;
  std::string error;
  REQUIRE(LoadStudyFile((RepoRoot() / "examples/calibrate_bp_rolling.json").string(), &study,
                        &error));
  return study;
}

}  // namespace

TEST_CASE("a calibration result carries the best candidate, its sigma and the residuals",
          "[unit][calibrate]") {
  const StudyFile study = ExampleStudy();
  calibrate::CalibrationSummary s;
  s.termination = demcal::calibrate::Termination::kWithinNoise;
  s.message = "matched within noise";
  s.candidates.resize(2);
  s.candidates[0].parameters = {0.1};
  s.candidates[1].parameters = {0.3};
  s.best = 1;
  s.estimates = {{"mu_r_BP_BP", 0.3, 0.02, true}};
  s.residuals = {{"BP angle", "angle_deg", 40.0, 1.0, 39.5, 0.4, -0.5, true}};
  const CalibrationResult r = CalibrationResultOf(study, s);
  CHECK(r.termination == demcal::calibrate::Termination::kWithinNoise);
  CHECK(r.message == "matched within noise");
  REQUIRE(r.parameters.size() == 1);
  CHECK(r.parameters[0].name == study.space.parameters[0].name);
  CHECK(r.parameters[0].property == "rolling_friction");
  CHECK(r.parameters[0].material_a == "BP");
  CHECK(r.parameters[0].value == 0.3);  // the best candidate's, not the first
  CHECK(r.parameters[0].sigma == 0.02);
  CHECK(r.parameters[0].identifiable);
  REQUIRE(r.targets.size() == 1);
  CHECK(r.targets[0].measured == 40.0);
  CHECK(r.targets[0].simulated == 39.5);
  CHECK(r.targets[0].sem == 0.4);
  CHECK(r.targets[0].within_noise);
  CHECK(r.targets[0].provenance == study.targets[0].provenance);
}

TEST_CASE("a calibration without a best candidate or a finite sigma says so", "[unit][calibrate]") {
  const StudyFile study = ExampleStudy();
  calibrate::CalibrationSummary s;  // no candidate at all
  CalibrationResult r = CalibrationResultOf(study, s);
  REQUIRE(r.parameters.size() == 1);
  CHECK(std::isnan(r.parameters[0].value));
  CHECK(std::isnan(r.parameters[0].sigma));
  s.candidates.resize(1);
  s.candidates[0].parameters = {0.2};
  s.best = 0;
  s.estimates = {{"mu_r_BP_BP", 0.2, std::numeric_limits<double>::infinity(), false}};
  r = CalibrationResultOf(study, s);
  CHECK(r.parameters[0].value == 0.2);
  CHECK(std::isnan(r.parameters[0].sigma));  // not determined: result.json writes null
  CHECK_FALSE(r.parameters[0].identifiable);
}

TEST_CASE("calibration statuses map to the command's exit codes", "[unit][calibrate]") {
  CHECK(ExitCodeOf(CalibrationStatus::kMatched) == kExitOk);
  CHECK(ExitCodeOf(CalibrationStatus::kNotMatched) == kExitRunFailed);
  CHECK(ExitCodeOf(CalibrationStatus::kInvalidInput) == kExitInvalidInput);
  CHECK(ExitCodeOf(CalibrationStatus::kOutputUnavailable) == kExitInvalidInput);
  CHECK(ExitCodeOf(CalibrationStatus::kOutputError) == kExitOutputError);
}
