// A base fitted onto a bound against the effects that let it back inside (JudgeBound,
// bound_alternative.h), on hand-made fits: 12 observations, single-run scatter q = 1 each, one
// fitted base parameter, every effect with one parameter (BIC penalty ln 12 = 2.48).
#include "diagnose/ranking/bound_alternative.h"

#include <catch2/catch.hpp>

#include "diagnose/ranking/discrepancy_floor.h"

namespace demcal::diagnose {
namespace {

const Eigen::VectorXd kQ = Eigen::VectorXd::Ones(12);

Evidence Base(double residual, double noise_sd = 0) {
  Evidence e;
  e.residuals = Eigen::VectorXd::Constant(12, residual);
  e.q = kQ;
  e.floor = EstimateFloor(e.residuals, kQ, 11);
  e.chi2_noise_sd = noise_sd;
  return e;
}

RankingEntry Fit(const std::string& key, double base_residual, double residual, bool control,
                 double noise_sd = 0) {
  RankingEntry e;
  e.key = key;
  e.simulated = true;
  e.control = control;
  e.evidence = EvidenceWithFloor(Eigen::VectorXd::Constant(12, base_residual),
                                 Eigen::VectorXd::Constant(12, residual), kQ, 1, 1, 0.01 / 3);
  e.evidence.chi2_noise_sd = noise_sd;
  return e;
}

}  // namespace

TEST_CASE("JudgeBound: an effect that fits as well as the bound is not told apart from it",
          "[unit]") {
  // The base at its bound fits within noise (χ² 12 on 11 dof), the effect with the parameter
  // inside better (χ² 7.68) by more than its BIC penalty: gap 7.68 + 2.48 − 12 = −1.84, within 6.
  const std::vector<RankingEntry> entries = {Fit("rolling", 1.0, 0.8, false),
                                             Fit("control", 1.0, 1.0, true)};
  const BoundJudgement j = JudgeBound(entries, {true, false}, {false, true}, Base(1.0));
  CHECK(j.verdict == BoundVerdict::kNotToldApart);
  CHECK(j.effect == 0);
  CHECK(j.alternative == -1);  // the control's refit, no better than the base, does not stand
  CHECK(j.bic_gap == Approx(7.68 + std::log(12.0) - 12.0).epsilon(1e-3));
  CHECK(j.within == Approx(kBicIndistinct));
  // Better by less than its penalty (χ² 9.72: gap +0.2) is not as good: the bound stands alone.
  const std::vector<RankingEntry> weaker = {Fit("rolling", 1.0, 0.9, false)};
  CHECK(JudgeBound(weaker, {true}, {false}, Base(1.0)).verdict == BoundVerdict::kBeyondRange);
}

TEST_CASE("JudgeBound: a clearly better, significant effect rules the bound out", "[unit]") {
  // A gap at the bound (χ² 108) that the control beyond the bound narrows (χ² 48) and the
  // effect closes (χ² 9.72) with the parameter inside.
  const std::vector<RankingEntry> entries = {Fit("rolling", 3.0, 0.9, false),
                                             Fit("control", 3.0, 2.0, true)};
  const BoundJudgement j = JudgeBound(entries, {true, false}, {false, true}, Base(3.0));
  CHECK(j.verdict == BoundVerdict::kEffect);
  CHECK(j.effect == 0);
  CHECK(j.alternative == 1);  // the control beyond the bound fits better than the base there
  CHECK(j.bic_gap == Approx(9.72 - 48.0).epsilon(1e-3));
}

TEST_CASE("JudgeBound: the same gap within the refits' simulation noise is a tie", "[unit]") {
  // Residuals 0.5 against the base's 1.0: BIC gap 3 + 2.48 − 12 = −6.5, "strong" for exact fits
  // and significant (Δχ² 9, p 0.003), but each χ² carries a noise sd of 5: 2·√50 = 14.1.
  const std::vector<RankingEntry> exact = {Fit("rolling", 1.0, 0.5, false)};
  CHECK(JudgeBound(exact, {true}, {false}, Base(1.0)).verdict == BoundVerdict::kEffect);
  const std::vector<RankingEntry> noisy = {Fit("rolling", 1.0, 0.5, false, 5.0)};
  const BoundJudgement j = JudgeBound(noisy, {true}, {false}, Base(1.0, 5.0));
  CHECK(j.verdict == BoundVerdict::kNotToldApart);
  CHECK(j.within == Approx(2 * std::sqrt(50.0)));
}

TEST_CASE("JudgeBound: the bound alternative fitting better asks for a wider range", "[unit]") {
  // The control beyond the bound: χ² 3 (gap to the base −6.5); the best effect inside: χ² 27.
  const std::vector<RankingEntry> entries = {Fit("rolling", 1.0, 1.5, false),
                                             Fit("control", 1.0, 0.5, true)};
  const BoundJudgement j = JudgeBound(entries, {true, false}, {false, true}, Base(1.0));
  CHECK(j.verdict == BoundVerdict::kBeyondRange);
  CHECK(j.alternative == 1);
  CHECK(j.bic_gap == Approx(27.0 - 3.0).epsilon(1e-3));
}

TEST_CASE("JudgeBound: a tie is no answer when an effect on the bound fits far better than both",
          "[unit]") {
  // The base at its bound χ² 108, the effect held inside χ² 60 (under its floor, φ² q² = 5:
  // 48/6 = 8 better than the base, gap −8 + 2.48, a tie), the size width's refit, still on the
  // bound, χ² 12: significant, and beyond the margin 2·√50 of both.
  const std::vector<RankingEntry> entries = {Fit("rolling", 3.0, std::sqrt(60.0 / 12), false, 5),
                                             Fit("size", 3.0, 1.0, false, 5)};
  const BoundJudgement j = JudgeBound(entries, {true, false}, {false, false}, Base(3.0, 5));
  CHECK(j.verdict == BoundVerdict::kOutranked);
  CHECK(j.effect == 0);
  CHECK(j.outranked_by == 1);
  // The same tie with the on-bound effect as poor as the tie: not told apart, as before.
  const std::vector<RankingEntry> level = {Fit("rolling", 3.0, std::sqrt(60.0 / 12), false, 5),
                                           Fit("size", 3.0, std::sqrt(58.0 / 12), false, 5)};
  CHECK(JudgeBound(level, {true, false}, {false, false}, Base(3.0, 5)).verdict ==
        BoundVerdict::kNotToldApart);
}

TEST_CASE("JudgeBound: effects still on the bound, controls and linear refits do not count",
          "[unit]") {
  std::vector<RankingEntry> entries = {Fit("rolling", 1.0, 0.5, false),
                                       Fit("control", 1.0, 0.5, true),
                                       Fit("shape", 1.0, 0.5, false)};
  entries[2].simulated = false;  // a linearised refit is a shortlist, not evidence
  // rolling's refit stayed on the bound; the control is inside but never an effect.
  const BoundJudgement j =
      JudgeBound(entries, {false, true, true}, {false, true, false}, Base(1.0));
  CHECK(j.verdict == BoundVerdict::kNoEffectInside);
  CHECK(j.effect == -1);
}

}  // namespace demcal::diagnose
