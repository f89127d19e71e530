// Calibration twins on the DEM (issue "Calibration II", proof): data made by demcal at known
// parameters plus measurement-like noise (datasets/synthetic/, recipes in scripts/), calibrated
// back through the same entry point as `demcal calibrate`, scored against truth.json, which only
// these tests read. Long ([.][long]: minutes each at quick fidelity); run them with
// `bash scripts/run_long_tests.sh`.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/io/scratch_dir.h"
#include "workflow/calibration/run_study.h"
#include "workflow/exit_codes.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"

using namespace demcal::workflow;
using demcal::testing::ReadJson;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;

namespace {

// Runs the study at quick fidelity into `out`, echoing the calibration's own log so a failure
// shows the summary (termination, residuals) and not only the exit code.
int CalibrateQuick(const std::string& study, const std::string& out) {
  CalibrateOptions o{study, out, /*quick=*/true, /*max_evaluations=*/0, /*threads=*/0, /*quiet=*/true};
  std::ostringstream log;
  const int code = RunCalibrate(o, log);
  std::cerr << log.str();
  return code;
}

double ParameterValue(const nlohmann::json& result, const std::string& name, const char* key) {
  for (const auto& p : result["parameters"])
    if (p["name"] == name) return p[key].get<double>();
  FAIL("result.json has no parameter " << name);
  return NAN;
}

}  // namespace

// Twin (a), one noise draw: the two-target example recovers the sliding and rolling friction
// the data were made with (truth.json: 0.5, 0.2) within 2 sigma of its own reported sigma.
TEST_CASE("two-target twin recovers both frictions within 2 sigma", "[.][long][calibrate]") {
  ScratchDir dir("twin_two_targets");
  const std::string study = (RepoRoot() / "examples/calibrate_bp_two_targets.json").string();
  REQUIRE(CalibrateQuick(study, dir.str("out")) == kExitOk);
  const nlohmann::json result = ReadJson(dir.str("out/result.json"));
  const nlohmann::json truth =
      ReadJson((RepoRoot() / "datasets/synthetic/bp_friction_twin/truth.json").string())["truth"];
  for (const auto& [name, key] : {std::pair{"mu_s_BP_BP", "sliding_friction"},
                                  std::pair{"mu_r_BP_BP", "rolling_friction"}}) {
    const double value = ParameterValue(result, name, "value");
    const double sigma = ParameterValue(result, name, "sigma");
    INFO(name << " = " << value << " +- " << sigma << ", truth " << truth[key]);
    REQUIRE(std::isfinite(sigma));
    CHECK(std::abs(value - truth[key].get<double>()) <= 2.0 * sigma);
  }
}
