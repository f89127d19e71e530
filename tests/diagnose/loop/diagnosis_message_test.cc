// "Gap not explained by the library" names the step's best simulated candidate when the data
// favour it over the base by ΔBIC < 0 short of significance/K, with the row its refit moves most
// toward the data (diagnosis_message.cc, BestNotNamedText); a candidate the data do not favour
// (ΔBIC ≥ 0), or the control, is not named there.
#include <catch2/catch.hpp>

#include "diagnose/loop/diagnosis_message.h"

namespace demcal::diagnose {
namespace {

const std::vector<CandidateEffect> kCandidates = {
    {"wider_sizes", "a stand-in", {{"w", "", -1, 1, 0.5, "wider", "narrower"}}},
    {"control", "a stand-in", {{"c", "", -1, 1, 0.5, "more", "less"}}, true}};

// A gap the base misses by 7 σ in row 1; candidate 0 refitted by simulation to w = 0.6, its
// refit moving row 1 to −2 σ, with the given ΔBIC and p (significance/K = 0.005).
Diagnosis GapNotExplained(double delta_bic, bool control = false) {
  Diagnosis d;
  d.termination = DiagnosisTermination::kModelFormOffset;
  d.before.resize(2);
  d.before[0].name = "angle", d.before[0].measured = 10, d.before[0].simulated = 10.5;
  d.before[1].name = "bulk density", d.before[1].measured = 585, d.before[1].simulated = 578;
  DiagnosisStep step;
  RankingEntry e;
  e.candidate = control ? 1 : 0;
  e.key = kCandidates[e.candidate].key;
  e.control = control;
  e.simulated = true;
  e.values = {0.6};
  e.evidence.delta_bic = delta_bic;
  e.evidence.lr_p_value = 0.0019;
  step.entries = {e};
  step.refit_residuals = {{0.4, -2.0}};
  step.ranking.order = {0};
  d.steps = {step};
  return d;
}

}  // namespace

TEST_CASE("a gap not explained names the best candidate the data favour short of alpha/K",
          "[unit]") {
  DiagnoseOptions options;
  options.significance = 0.01;
  const std::string m = DiagnosisMessage(GapNotExplained(-10.0), options, kCandidates);
  CHECK(m.find("gap not explained by the library") != std::string::npos);
  CHECK(m.find("the best candidate, not named: wider_sizes (wider") != std::string::npos);
  CHECK(m.find("not below significance/K = 0.01") != std::string::npos);  // K = 1 here
  CHECK(m.find("its refit moves bulk density from -7 to -2 sigma") != std::string::npos);
  // The data do not favour it (ΔBIC ≥ 0), or it is the control: nothing more is said.
  CHECK(DiagnosisMessage(GapNotExplained(1.0), options, kCandidates).find("best candidate") ==
        std::string::npos);
  CHECK(DiagnosisMessage(GapNotExplained(-10.0, true), options, kCandidates)
            .find("best candidate") == std::string::npos);
}

}  // namespace demcal::diagnose
