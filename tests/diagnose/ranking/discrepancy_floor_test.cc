// The discrepancy floor estimated from the data and the F test that judges an effect against
// it (discrepancy_floor.h, f_distribution.h, evidence.h), and the floor's false-alarm rate on
// analytic stand-ins (analytic_forward_model.h): pure noise plus a model-form offset.
#include "diagnose/ranking/discrepancy_floor.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/chi_square.h"
#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/diagnosis.h"
#include "diagnose/ranking/evidence.h"
#include "diagnose/ranking/f_distribution.h"

namespace demcal::diagnose {

TEST_CASE("F distribution tail against tabulated critical values", "[unit]") {
  // Upper 5 % and 1 % points of F (Abramowitz & Stegun 1964, Table 26.9).
  CHECK(FSurvival(5.59, 1, 7) == Approx(0.05).epsilon(0.01));
  CHECK(FSurvival(4.10, 2, 10) == Approx(0.05).epsilon(0.01));
  CHECK(FSurvival(2.71, 5, 20) == Approx(0.05).epsilon(0.01));
  CHECK(FSurvival(10.04, 1, 10) == Approx(0.01).epsilon(0.01));
  // F(1, ν) is the square of Student's t with ν dof: t_0.025,10 = 2.228.
  CHECK(FSurvival(2.228 * 2.228, 1, 10) == Approx(0.05).epsilon(0.01));
  CHECK(FSurvival(0, 1, 5) == 1);
  CHECK(RegularisedIncompleteBeta(1, 1, 0.3) == Approx(0.3));  // uniform
}

TEST_CASE("the floor is the Paule-Mandel moment estimate, zero within noise", "[unit]") {
  const Eigen::VectorXd r = Eigen::VectorXd::Constant(10, 2.0),
                        q = Eigen::VectorXd::Constant(10, 0.5);
  // Σ 4 / (1 + φ²/4) = 10 · 1  →  φ² = 12.
  CHECK(EstimateFloor(r, q, 10) == Approx(std::sqrt(12.0)).epsilon(1e-6));
  CHECK(FlooredChi2(r, q, std::sqrt(12.0)) == Approx(10));
  CHECK(EstimateFloor(Eigen::VectorXd::Constant(10, 0.9), q, 10) == 0);  // χ² 8.1 below 10 dof
  // An improvement judged against the floor: with the floor estimated the F test, not χ².
  Eigen::VectorXd r1 = r;
  r1.head(5).setZero();
  const Evidence e = EvidenceWithFloor(r, r1, q, 1, 1, 0.01);
  CHECK(e.floor > 0);
  CHECK(e.lr_p_value == Approx(FSurvival(e.delta_chi2, 1, 8)));
  CHECK(e.lr_p_value > calibrate::ChiSquareSurvival(e.delta_chi2, 1));
}

namespace {

// Diagnoses a dataset with nothing hidden at mu = 0.5: noise of the stated uncertainties plus a
// model-form offset of `offset` single-run scatters (a fresh draw per seed).
Diagnosis Clean(uint64_t seed, double offset) {
  testing::AnalyticForwardModel model;
  const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {}, seed, 0, offset);
  return Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
}

}  // namespace

TEST_CASE("the estimated floor keeps false alarms at the significance on noise plus an offset",
          "[unit]") {
  // 200 seeded datasets per offset, significance 0.01: a rule at its nominal level names an
  // effect in at most 7 of 200 but with probability 0.001 (binomial tail; expected 2).
  for (double offset : {0.0, 3.0}) {
    int gaps = 0, named = 0, offsets = 0;
    for (uint64_t seed = 1; seed <= 200; ++seed) {
      const Diagnosis d = Clean(seed, offset);
      gaps += d.gap_before.gap_detected;
      named += !d.named.empty();
      offsets += d.termination == DiagnosisTermination::kModelFormOffset;
    }
    INFO("offset " << offset << " scatters: gap " << gaps << ", effect named " << named
                   << ", model-form offset " << offsets << " of 200");
    CHECK(named <= 7);
    // The offset is large enough to be a gap in most draws: the floor, not the gap test, keeps
    // them from being called effects.
    if (offset > 0) CHECK(gaps >= 100);
  }
}

TEST_CASE("an effect is still named through the floor of a model-form offset", "[unit]") {
  // Shape hidden at 0.8 under a 3-scatter offset: the effect explains more than the floor allows.
  int named = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    testing::AnalyticForwardModel model;
    const std::vector<Observation> obs =
        testing::MakeObservations(&model, 0.5, {{2, 0.8}}, seed, 0, 3.0);
    const Diagnosis d = Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
    named += !d.named.empty() && testing::Candidates()[d.named[0]].key == "shape";
    for (int c : d.named) CHECK(testing::Candidates()[c].key != "control");
  }
  CHECK(named >= 8);
}

}  // namespace demcal::diagnose
