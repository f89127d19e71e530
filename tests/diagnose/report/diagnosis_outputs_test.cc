// The files `demcal diagnose` writes (diagnosis_outputs.h), from diagnoses of the analytic
// stand-in: the sign of a named effect, the estimated floor, the settled base, a tie with the
// measurement that would separate it, and the control guard reach diagnosis.json, ranking.csv
// and report.html.
#include "diagnose/report/diagnosis_outputs.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/io/scratch_dir.h"
#include "diagnose/analytic_forward_model.h"
#include "workflow/tiny_scene.h"

namespace demcal::diagnose {
namespace {

using demcal::testing::ReadJson;
using demcal::testing::ScratchDir;

nlohmann::json Written(const ScratchDir& dir, const std::string& name,
                       const std::vector<CandidateEffect>& candidates, const Diagnosis& d) {
  DiagnosisRunInfo info{"study.json", "stand-in"};
  info.synthetic = true;
  info.data_provenance = {"simulated:liggghts-3.8"};
  info.candidates = candidates;
  info.base_names = {"mu"};
  std::string error;
  std::filesystem::create_directories(dir.str(name));  // the command's output lock makes it
  INFO(error);
  REQUIRE(WriteDiagnosisOutputs(dir.str(name), info, d, &error));
  return ReadJson(dir.str(name + "/diagnosis.json"));
}

std::string Text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("diagnosis outputs carry the sign, the floor, the base and the tie", "[unit]") {
  ScratchDir dir("diagnosis_outputs");
  testing::AnalyticForwardModel model;
  std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {{1, -0.2}}, 1);
  Diagnosis signed_effect = Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
  REQUIRE(signed_effect.before.size() >= 3);
  signed_effect.before[0].source = signed_effect.before[2].source = 7;  // one simulated scene
  signed_effect.before[1].source = -1;
  nlohmann::json j = Written(dir, "signed", testing::Candidates(), signed_effect);
  CHECK(j["residuals_before"][0]["simulated_source"] == 7);
  CHECK(j["residuals_before"][1]["simulated_source"].is_null());
  CHECK(j["residuals_before"][2]["simulated_source"] == 7);
  CHECK(j["termination"] == "effect_found");
  CHECK(j["named_effects_signed"][0]["direction"] == "less rolling resistance than assumed");
  CHECK(j["named_effects_signed"][0]["value"].get<double>() < 0);
  CHECK(j["discrepancy_floor"]["fixed_single_run_scatters"] == 1.0);
  CHECK(j["discrepancy_floor"]["estimated_single_run_scatters_before"].is_number());
  CHECK(j["base_calibration"]["settled"] == true);
  CHECK(j["base_calibration"]["identifiable"] == true);
  CHECK(j["provenance"]["data_provenance"][0] == "simulated:liggghts-3.8");
  CHECK(
      Text(dir.str("signed/ranking.csv")).rfind("step,rank,effect,parameter,value,direction,", 0) ==
      0);
  CHECK(Text(dir.str("signed/report.html")).find("less rolling resistance than assumed") !=
        std::string::npos);

  testing::AnalyticForwardModel tie_model;
  obs = testing::MakeObservations(&tie_model, 0.5, {{1, 0.35}}, 1);
  const std::vector<CandidateEffect> ambiguous = testing::AmbiguousCandidates();
  const Diagnosis tie = Diagnose(tie_model, obs, ambiguous, DiagnoseOptions{});
  j = Written(dir, "tie", ambiguous, tie);
  CHECK(j["termination"] == "not_told_apart");
  CHECK(j["named_effect"].is_null());
  CHECK(j["not_told_apart"].size() == 2);
  CHECK(j["separating_measurement"]["observable"].is_string());
  CHECK(j["steps"][0]["not_told_apart_from"].is_string());

  std::vector<CandidateEffect> guarded = testing::Candidates();
  guarded[2].control = true;
  testing::AnalyticForwardModel control_model;
  obs = testing::MakeObservations(&control_model, 0.5, {{2, 0.8}}, 1);
  const Diagnosis control = Diagnose(control_model, obs, guarded, DiagnoseOptions{});
  j = Written(dir, "control", guarded, control);
  CHECK(j["termination"] == "model_form_offset");
  CHECK(j["control_guard"].is_string());
  CHECK(j["steps"][0]["control_first"] == true);
  CHECK(j["screen"].is_null());  // a gap: no screen
}

TEST_CASE("diagnosis.json gives the screen's directed p beside the omnibus p", "[unit]") {
  // Shape at 0.15, below what the gap test flags in most datasets (screen_test.cc): the first
  // dataset without a gap in which the screen names it.
  ScratchDir dir("diagnosis_outputs_screen");
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    testing::AnalyticForwardModel model;
    model.seed = 100000 + seed;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {{2, 0.15}}, seed);
    const Diagnosis d = Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
    if (d.gap_before.gap_detected || d.named.empty()) continue;
    const nlohmann::json j = Written(dir, "screen", testing::Candidates(), d);
    CHECK(j["termination"] == "effect_found");
    CHECK(j["screen"]["best_candidate"] == "shape");
    CHECK(j["screen"]["best_refit"] == "simulated");
    CHECK(j["screen"]["best_significant"] == true);
    CHECK(j["screen"]["best_lr_p_value"].get<double>() <
          j["screen"]["significance_per_candidate"].get<double>());
    CHECK(j["screen"]["omnibus_chi2_p_value"].get<double>() >= 0.005);  // α/2: no gap
    CHECK(j["provenance"]["screen_without_gap"] == true);
    return;
  }
  FAIL("no dataset without a gap named shape");
}

}  // namespace demcal::diagnose

namespace demcal::diagnose {

TEST_CASE("a re-valued parameter and a named effect reach the outputs apart", "[unit]") {
  // Shape (added) and less rolling resistance than an assumed 0.3 (re-valued) together
  // (revaluation_test.cc): the named effect in named_effects_signed, the re-valued one in
  // revalued_parameters only, both in diagnosed_params.json with their roles, and the report
  // tags each step's winner with what became of it.
  ScratchDir dir("diagnosis_outputs_revalued");
  testing::AnalyticForwardModel model;
  const std::vector<Observation> obs =
      testing::MakeObservations(&model, 0.5, {{1, -0.25}, {2, 0.6}}, 1);
  std::vector<CandidateEffect> candidates = testing::Candidates();
  candidates[1].parameters[0].assumed = 0.3;
  const Diagnosis d = Diagnose(model, obs, candidates, DiagnoseOptions{});
  const nlohmann::json j = Written(dir, "both", candidates, d);
  CHECK(j["termination"] == "effect_found");
  REQUIRE(j["named_effects_signed"].size() == 1);
  CHECK(j["named_effects_signed"][0]["effect"] == "shape");
  REQUIRE(j["revalued_parameters"].size() == 1);
  CHECK(j["revalued_parameters"][0]["effect"] == "rolling");
  CHECK(j["revaluation_tied_with"].is_null());
  CHECK(j["after_fit"] == "named_effects");
  const nlohmann::json params = ReadJson(dir.str("both/diagnosed_params.json"));
  REQUIRE(params["effects"].size() == 2);
  std::set<std::string> roles;
  for (const nlohmann::json& e : params["effects"])
    roles.insert(e["effect"].get<std::string>() + ":" + e["role"].get<std::string>());
  CHECK(roles == std::set<std::string>{"shape:named", "rolling:revalued"});
  const std::string html = Text(dir.str("both/report.html"));
  CHECK(html.find("(named)") != std::string::npos);
  CHECK(html.find("(re-valued, not named)") != std::string::npos);
}

}  // namespace demcal::diagnose

namespace demcal::diagnose {

TEST_CASE("the detection limits reach diagnosis.json and the report", "[unit]") {
  // Nothing hidden: "no missing effect", with what the data could not have seen.
  ScratchDir dir("diagnosis_outputs_limits");
  testing::AnalyticForwardModel model;
  const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {}, 1);
  const Diagnosis d = Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
  REQUIRE(d.termination == DiagnosisTermination::kNoMissingEffect);
  const nlohmann::json j = Written(dir, "limits", testing::Candidates(), d);
  REQUIRE(j["detection_limits"]["power"] == 0.9);
  const nlohmann::json& effects = j["detection_limits"]["effects"];
  REQUIRE(effects.size() == 4);  // the control is not listed
  std::set<std::string> keys;
  for (const nlohmann::json& e : effects) {
    keys.insert(e["effect"].get<std::string>());
    const double m = e["magnitude_at_power"].get<double>();
    if (e["effect"] == "rolling") {  // signed: both directions within [-0.3, 1] when m <= 0.3
      if (m <= 0.3) CHECK(e["smallest_detectable_decrease"].get<double>() == Approx(-m));
      CHECK(e["smallest_detectable_increase"].get<double>() == Approx(m));
    } else {
      CHECK(e["smallest_detectable_decrease"].is_null());  // these cannot fall below the base
    }
  }
  CHECK(keys == std::set<std::string>{"adhesion", "rolling", "shape", "polydispersity"});
  const std::string html = Text(dir.str("limits/report.html"));
  CHECK(html.find("What the data could not see") != std::string::npos);
  CHECK(html.find("smaller ones can hide") != std::string::npos);
}

}  // namespace demcal::diagnose
