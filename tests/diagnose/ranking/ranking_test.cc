#include "diagnose/ranking/ranking.h"

#include <catch2/catch.hpp>
#include <cmath>

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

}  // namespace demcal::diagnose
