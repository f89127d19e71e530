#include "diagnose/ranking/ranking.h"

#include <catch2/catch.hpp>
#include <cmath>

namespace demcal::diagnose {
namespace {

RankingEntry Entry(const std::string& key, double chi2_base, double chi2, bool simulated) {
  RankingEntry e;
  e.key = key;
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
  std::vector<RankingEntry> entries = {Entry("a", 50, 30, true), Entry("b", 50, 8, true), Entry("c", 50, 2, false)};
  Ranking r = RankCandidates(entries);
  CHECK(r.order.front() == 2);  // best ΔBIC, but only linearised: cannot win
  REQUIRE(r.winner == 1);
  CHECK(r.distinguished);
  entries[0] = Entry("a", 50, 9, true);  // within 2 of b's ΔBIC
  r = RankCandidates(entries);
  CHECK(r.winner == 1);
  CHECK_FALSE(r.distinguished);
  CHECK(r.message.find("not told apart from a") != std::string::npos);
  entries = {Entry("a", 12, 9, true)};  // Δχ² = 3: nothing significant
  r = RankCandidates(entries);
  CHECK(r.winner == -1);
}

}  // namespace demcal::diagnose
