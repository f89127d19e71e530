// Calibration twins on the DEM (proof of the calibration): data made by demcal at known
// parameters plus measurement-like noise (datasets/synthetic/, recipes in scripts/), calibrated
// back through the same entry point as `demcal calibrate`, scored against truth.json, which only
// these tests read. Long ([.][long]: minutes each at quick fidelity); run them with
// `bash scripts/run_long_tests.sh`.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

#include "core/io/scratch_dir.h"
#include "workflow/calibration/run_study.h"
#include "outputs/exit_codes.h"
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

// σ of a parameter; +inf when result.json gives none (null: not determined by the targets).
double ParameterSigma(const nlohmann::json& result, const std::string& name) {
  for (const auto& p : result["parameters"])
    if (p["name"] == name) return p["sigma"].is_number() ? p["sigma"].get<double>() : INFINITY;
  FAIL("result.json has no parameter " << name);
  return NAN;
}

}  // namespace

// The two-target example at truth mu_s 0.5, mu_r 0.2 (truth.json): above mu_s ≈ 0.4 the repose
// angle of these spheres no longer responds to mu_s and the funnel target is too noisy to pin it
// (docs/calibration.md, "Which targets separate mu_s and mu_r"), so a finite, correct sigma
// cannot be asked of this twin (the rig twin below is the identifiable one). What is asked: no
// confident wrong answer — each parameter either reports sigma = +inf (undetermined) or lies
// within 2 sigma of the truth. (A run that ended at mu_s = 1.00 +- 0.03 would fail.)
TEST_CASE("two-target twin at mu_s 0.5 gives no confident wrong answer", "[.][long][calibrate]") {
  ScratchDir dir("twin_two_targets");
  const std::string study = (RepoRoot() / "examples/calibrate_bp_two_targets.json").string();
  const int code = CalibrateQuick(study, dir.str("out"));
  REQUIRE((code == kExitOk || code == kExitRunFailed));  // 3: not matched within noise
  const nlohmann::json result = ReadJson(dir.str("out/result.json"));
  const nlohmann::json truth =
      ReadJson((RepoRoot() / "datasets/synthetic/bp_friction_twin/truth.json").string())["truth"];
  for (const auto& [name, key] : {std::pair{"mu_s_BP_BP", "sliding_friction"},
                                  std::pair{"mu_r_BP_BP", "rolling_friction"}}) {
    const double value = ParameterValue(result, name, "value");
    const double sigma = ParameterSigma(result, name);
    WARN(name << " = " << value << " +- " << sigma << ", truth " << truth[key]);
    if (std::isfinite(sigma)) CHECK(std::abs(value - truth[key].get<double>()) <= 2.0 * sigma);
  }
}

namespace {

// The rig twin's study with noise draw k: its own measurement table and its own base seed (so
// the recoveries differ by measurement noise *and* packings, the two things σ accounts for).
std::string RigStudy(const ScratchDir& dir, int k) {
  nlohmann::json s = ReadJson((RepoRoot() / "examples/calibrate_bp_friction_rig.json").string());
  s["measurements"] = (RepoRoot() / ("datasets/synthetic/bp_friction_rig_twin/measurements_noise" +
                                     std::to_string(k) + ".csv")).string();
  for (const char* list : {"targets", "candidate_targets"})
    for (auto& t : s[list]) t["experiment_file"] = (RepoRoot() / "examples" / t["experiment_file"].get<std::string>()).string();
  s["seed"] = 2018 + k;
  const std::string path = dir.str("study_" + std::to_string(k) + ".json");
  std::ofstream(path) << s.dump(2);
  return path;
}

double SampleSd(const std::vector<double>& x) {
  double mean = 0, ss = 0;
  for (double v : x) mean += v / x.size();
  for (double v : x) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / (x.size() - 1));
}

}  // namespace

// Twin (a), σ against the spread: the small-rig study (angle + discharge time, truth μs 0.25,
// μr 0.10) on five noise draws, each with its own seed. Every draw must report a finite σ, at
// most one of the five may miss the truth by more than 2σ (below), and the root-mean-square σ
// must lie within a factor 3 of the sample spread of the five recoveries (asked: "neither 3× too
// small nor 3× too large"; five draws estimate a spread to about ±35 %, hence the wide factor).
TEST_CASE("rig twin: sigma agrees with the spread of recoveries over five noise draws", "[.][long][calibrate]") {
  ScratchDir dir("twin_rig");
  const nlohmann::json truth =
      ReadJson((RepoRoot() / "datasets/synthetic/bp_friction_rig_twin/truth.json").string())["truth"];
  std::map<std::string, std::vector<double>> values, sigmas;
  for (int k = 1; k <= 5; ++k) {
    const std::string out = dir.str("out_" + std::to_string(k));
    const int code = CalibrateQuick(RigStudy(dir, k), out);
    REQUIRE((code == kExitOk || code == kExitRunFailed));  // 3: not matched within noise
    const nlohmann::json result = ReadJson(out + "/result.json");
    for (const auto& p : result["parameters"]) {
      values[p["name"]].push_back(p["value"].get<double>());
      sigmas[p["name"]].push_back(ParameterSigma(result, p["name"]));
    }
  }
  for (const auto& [name, key] : {std::pair{"mu_s_BP_BP", "sliding_friction"},
                                  std::pair{"mu_r_BP_BP", "rolling_friction"}}) {
    const std::vector<double>& v = values[name];
    const std::vector<double>& s = sigmas[name];
    REQUIRE(v.size() == 5);
    // Each recovery against the truth in units of its own σ. With an honest σ a draw falls
    // outside 2σ with probability ≈ 5 %: requiring all five inside would fail a correct σ in
    // 23 % of runs (1 − 0.95⁵); at most one of five outside fails it in 2.3 %.
    double ms = 0;
    int outside = 0;
    for (size_t k = 0; k < v.size(); ++k) {
      const double z = (v[k] - truth[key].get<double>()) / s[k];
      WARN(name << " draw " << k + 1 << ": " << v[k] << " +- " << s[k] << " (z = " << z
                << "), truth " << truth[key]);
      CHECK(std::isfinite(s[k]));
      outside += !(std::abs(z) <= 2.0);
      ms += s[k] * s[k] / v.size();
    }
    CHECK(outside <= 1);
    const double spread = SampleSd(v), rms_sigma = std::sqrt(ms);
    WARN(name << ": spread of recoveries " << spread << ", rms sigma " << rms_sigma);
    CHECK(rms_sigma <= 3 * spread);
    CHECK(rms_sigma >= spread / 3);
  }
}

// Twin (c), Γ per coating level: BP heaps at 1, 2 and 3 wt% PEG with the BP-BP interfacial
// energy on the line Γ(w) = 0.004 + 0.006 w J/m² (datasets/synthetic/bp_gamma_curve_twin/,
// scripts/make_twin_gamma_curve.py), friction held at the heap file's own. Recovered per level
// (examples/calibrate_bp_gamma_per_level.json: one Γ per level, non-decreasing) and as a curve
// (examples/calibrate_bp_gamma_curve.json: both coefficients jointly): every value finite-σ and
// within 2σ of the truth, and the curve's slope resolved (more than 2σ above zero; the truth is
// ≈ 4.5σ above it, so a correct fit misses that in < 1 % of draws).
TEST_CASE("gamma twin: three coating levels recovered per level and as a linear curve", "[.][long][calibrate]") {
  ScratchDir dir("twin_gamma");
  const nlohmann::json truth =
      ReadJson((RepoRoot() / "datasets/synthetic/bp_gamma_curve_twin/truth.json").string());
  auto check_within_2_sigma = [](const nlohmann::json& result, const std::string& name, double want) {
    const double value = ParameterValue(result, name, "value"), sigma = ParameterSigma(result, name);
    WARN(name << " = " << value << " +- " << sigma << ", truth " << want << " (z = " << (value - want) / sigma << ")");
    CHECK(std::isfinite(sigma));
    CHECK(std::abs(value - want) <= 2 * sigma);
  };
  const std::string per_level = (RepoRoot() / "examples/calibrate_bp_gamma_per_level.json").string();
  REQUIRE(CalibrateQuick(per_level, dir.str("per_level")) == kExitOk);
  const nlohmann::json levels = ReadJson(dir.str("per_level/result.json"));
  for (const char* w : {"1", "2", "3"})
    check_within_2_sigma(levels, std::string("gamma_w") + w, truth["gamma_J_m2"][w].get<double>());

  const std::string curve = (RepoRoot() / "examples/calibrate_bp_gamma_curve.json").string();
  REQUIRE(CalibrateQuick(curve, dir.str("curve")) == kExitOk);
  const nlohmann::json fit = ReadJson(dir.str("curve/result.json"));
  check_within_2_sigma(fit, "gamma_0", truth["truth"]["C0_J_m2"].get<double>());
  check_within_2_sigma(fit, "gamma_per_wt_pct", truth["truth"]["C1_J_m2_per_wt_pct"].get<double>());
  CHECK(ParameterValue(fit, "gamma_per_wt_pct", "value") > 2 * ParameterSigma(fit, "gamma_per_wt_pct"));
}
