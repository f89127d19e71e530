#include "diagnose/ranking/ranking.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "diagnose/ranking/discrepancy_floor.h"

namespace demcal::diagnose {
namespace {

RankingEntry Entry(const std::string& key, double chi2_base, double chi2, bool simulated,
                   bool control = false) {
  RankingEntry e;
  e.key = key;
  e.control = control;
  e.simulated = simulated;
  e.chi2 = chi2;
  e.evidence = EvidenceOf(chi2_base, chi2, 1, 12, 0.01);
  return e;
}

// The standard deviation of the floored χ² over 40000 draws of the simulated means, each source
// one error (source[i]: row i's; empty: every row its own) of its rows' standard errors u.
double SampledChi2Sd(const Eigen::VectorXd& r, const Eigen::VectorXd& u, const Eigen::VectorXd& q,
                     double phi, const std::vector<int>& source, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> z(0, 1);
  const int draws = 40000;
  double sum = 0, sum2 = 0;
  for (int k = 0; k < draws; ++k) {
    std::map<int, double> error;  // per source, this draw's
    Eigen::VectorXd rr = r;
    for (int i = 0; i < rr.size(); ++i) {
      const int s = source.empty() ? i : source[i];
      if (!error.count(s)) error[s] = z(rng);
      rr(i) += u(i) * error[s];
    }
    const double c = FlooredChi2(rr, q, phi);
    sum += c, sum2 += c * c;
  }
  return std::sqrt(sum2 / draws - (sum / draws) * (sum / draws));
}

}  // namespace

TEST_CASE("evidence: ΔBIC with the Schwarz penalty and the Wilks likelihood ratio", "[unit]") {
  const Evidence e = EvidenceOf(40, 10, 1, 12, 0.01);
  CHECK(e.delta_chi2 == 30);
  CHECK(e.delta_bic == Approx(-30 + std::log(12.0)));
  CHECK(e.lr_p_value < 1e-6);
  CHECK(e.significant);
  // Δχ² = 5 with k = 1: p = 0.025 — not significant at 0.01 although ΔBIC < 0.
  const Evidence weak = EvidenceOf(20, 15, 1, 12, 0.01);
  CHECK(weak.delta_bic < 0);
  CHECK_FALSE(weak.significant);
}

TEST_CASE("ranking names the best simulated significant candidate and flags a near tie", "[unit]") {
  std::vector<RankingEntry> entries = {Entry("a", 50, 30, true), Entry("b", 50, 8, true),
                                       Entry("c", 50, 2, false)};
  Ranking r = RankCandidates(entries);
  CHECK(r.order.front() == 2);  // best ΔBIC, but only linearised: cannot win
  REQUIRE(r.winner == 1);
  CHECK(r.distinguished);
  entries[0] = Entry("a", 50, 9, true);  // within kBicIndistinct of b's ΔBIC
  r = RankCandidates(entries);
  CHECK(r.winner == 1);
  CHECK_FALSE(r.distinguished);
  CHECK(r.message.find("not told apart from a") != std::string::npos);
  entries = {Entry("a", 12, 9, true)};  // Δχ² = 3: nothing significant
  r = RankCandidates(entries);
  CHECK(r.winner == -1);
}

TEST_CASE("ranking: a tie is named, and the control never wins", "[unit]") {
  std::vector<RankingEntry> entries = {Entry("a", 50, 10, true), Entry("b", 50, 11, true),
                                       Entry("c", 50, 30, true)};
  Ranking r = RankCandidates(entries);
  CHECK(r.winner == 0);
  CHECK(r.tied == 1);
  CHECK_FALSE(r.control_first);
  // The control ranks first: no winner, a model-form offset.
  entries = {Entry("a", 50, 20, true), Entry("control", 50, 5, true, true)};
  r = RankCandidates(entries);
  CHECK(r.winner == -1);
  CHECK(r.control_first);
  CHECK(r.message.find("model-form offset") != std::string::npos);
  // The control level with the winner (ΔBIC within kBicIndistinct): an effect no better than re-tuning a fitted
  // parameter is not named either.
  entries = {Entry("a", 50, 10, true), Entry("control", 50, 11, true, true)};
  r = RankCandidates(entries);
  CHECK(r.winner == -1);
  CHECK(r.control_first);
  // Far behind the winner, the control does not matter.
  entries = {Entry("a", 50, 5, true), Entry("control", 50, 40, true, true)};
  r = RankCandidates(entries);
  CHECK(r.winner == 0);
  CHECK_FALSE(r.control_first);
}

TEST_CASE("evidence: the χ² noise of a simulated refit by the delta method", "[unit]") {
  // Var(Σ w r²) = Σ 4 r² w² u² to first order: r = 2, u = 0.5 on four observations gives 16.
  const Eigen::VectorXd r = Eigen::VectorXd::Constant(4, 2.0);
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(4, 0.5);
  const Eigen::VectorXd q = Eigen::VectorXd::Ones(4);
  CHECK(Chi2NoiseSd(r, u, q, 0) == Approx(4.0));
  CHECK(Chi2NoiseSd(r, u, q, 1) == Approx(2.0));  // the floor halves each weight
  // Against sampling: means perturbed by their standard errors; exact variance adds Σ 2 w² u⁴,
  // negligible here (0.3 % of the first-order term).
  const Eigen::VectorXd r2 = (Eigen::VectorXd(6) << 3, -2, 1.5, -3, 2.5, 0.5).finished();
  const Eigen::VectorXd u2 = (Eigen::VectorXd(6) << 0.2, 0.3, 0.1, 0.25, 0.15, 0.3).finished();
  const Eigen::VectorXd q2 = (Eigen::VectorXd(6) << 1, 2, 0.5, 1, 1.5, 1).finished();
  const double phi = 0.7;
  const double sd = SampledChi2Sd(r2, u2, q2, phi, {}, 7);
  CHECK(Chi2NoiseSd(r2, u2, q2, phi) == Approx(sd).epsilon(0.03));
}

TEST_CASE("evidence: rows of one simulated mean share its error in the chi2 noise", "[unit]") {
  // Six rows, three sources (one simulated scene read by two table rows each: a scene run once
  // for two conditions that do not enter the model). One error per source moves both its rows:
  // against sampling with one draw per source, the grouped delta method holds and the rows
  // counted as independent fall short (same-sign pairs: by up to √2).
  const Eigen::VectorXd r = (Eigen::VectorXd(6) << 3, 2.5, -2, -1.5, 1, 2).finished();
  const Eigen::VectorXd u = (Eigen::VectorXd(6) << 0.2, 0.2, 0.3, 0.3, 0.25, 0.25).finished();
  const Eigen::VectorXd q = (Eigen::VectorXd(6) << 1, 1, 2, 2, 1.5, 1.5).finished();
  const std::vector<int> source = {4, 4, 9, 9, 2, 2};
  const double phi = 0.7;
  const double sd = SampledChi2Sd(r, u, q, phi, source, 11);
  CHECK(Chi2NoiseSd(r, u, q, phi, source) == Approx(sd).epsilon(0.03));
  CHECK(Chi2NoiseSd(r, u, q, phi) < 0.8 * sd);
  // Every row its own source: as without sources.
  CHECK(Chi2NoiseSd(r, u, q, phi, {0, 1, 2, 3, 4, 5}) == Approx(Chi2NoiseSd(r, u, q, phi)));
}

TEST_CASE("ranking: a gap within the refits' simulation noise is not told apart", "[unit]") {
  // ΔBIC 10 apart: beyond kBicIndistinct, told apart when the refits were exact.
  std::vector<RankingEntry> entries = {Entry("a", 50, 10, true), Entry("b", 50, 20, true)};
  Ranking r = RankCandidates(entries);
  CHECK(r.winner == 0);
  CHECK(r.distinguished);
  // Each refit's χ² uncertain by 4: the difference by 4√2, two of which (11.3) exceed the gap.
  entries[0].evidence.chi2_noise_sd = entries[1].evidence.chi2_noise_sd = 4;
  r = RankCandidates(entries);
  CHECK(r.winner == 0);
  CHECK_FALSE(r.distinguished);
  CHECK(r.tied == 1);
  CHECK(IndistinctWithin(entries[0].evidence, entries[1].evidence) == Approx(8 * std::sqrt(2.0)));
  // A clear winner is still named: ΔBIC 35 apart with the same noise.
  entries[1] = Entry("b", 50, 45, true);
  entries[1].evidence.chi2_noise_sd = 4;
  r = RankCandidates(entries);
  CHECK(r.winner == 0);
  CHECK(r.distinguished);
  CHECK(r.tied == -1);
  // A noisy control 10 behind the winner is level with it: the control guard holds.
  entries = {Entry("a", 50, 10, true), Entry("control", 50, 20, true, true)};
  entries[1].evidence.chi2_noise_sd = 6;
  r = RankCandidates(entries);
  CHECK(r.winner == -1);
  CHECK(r.control_first);
}

}  // namespace demcal::diagnose
