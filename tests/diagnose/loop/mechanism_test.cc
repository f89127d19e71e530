// Two laws of one mechanism (ranking.h, diagnosis.h): when the runner-up that the data do not
// tell apart from the winner is another law of the winner's mechanism (JKR and sjkr adhesion),
// the mechanism is named as the found effect with the better-fitting law and "law not told
// apart"; laws of different mechanisms still tie. Stand-ins: the analytic model's "rolling" and
// "roughness", whose signatures agree within a few per cent, declared one mechanism or two.
#include <catch2/catch.hpp>
#include <set>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/diagnosis.h"
#include "diagnose/ranking/ranking.h"

namespace demcal::diagnose {
namespace {

RankingEntry Entry(const std::string& key, const std::string& mechanism, double chi2) {
  RankingEntry e;
  e.key = key;
  e.mechanism = mechanism;
  e.simulated = true;
  e.chi2 = chi2;
  e.evidence = EvidenceOf(50, chi2, 1, 12, 0.01);
  return e;
}

}  // namespace

TEST_CASE("ranking: two laws of one mechanism level with each other are no tie", "[unit]") {
  // b wins; a is within kBicIndistinct of it.
  std::vector<RankingEntry> entries = {Entry("a", "adhesion", 11), Entry("b", "adhesion", 10)};
  Ranking r = RankCandidates(entries);
  CHECK(r.winner == 1);
  CHECK(r.tied == -1);
  CHECK(r.same_mechanism == 0);
  CHECK(r.distinguished);
  CHECK(r.message.find("law not told apart from a (same mechanism, adhesion") !=
        std::string::npos);
  // Different mechanisms, or none declared: a tie as before.
  for (const std::string& other : {std::string("shape"), std::string()}) {
    entries = {Entry("a", other, 11), Entry("b", "adhesion", 10)};
    r = RankCandidates(entries);
    CHECK(r.winner == 1);
    CHECK(r.tied == 0);
    CHECK(r.same_mechanism == -1);
    CHECK_FALSE(r.distinguished);
  }
  entries = {Entry("a", "", 11), Entry("b", "", 10)};  // undeclared never match each other
  CHECK(RankCandidates(entries).tied == 0);
  // Far apart, the other law is simply beaten.
  entries = {Entry("a", "adhesion", 40), Entry("b", "adhesion", 10)};
  r = RankCandidates(entries);
  CHECK(r.same_mechanism == -1);
  CHECK(r.tied == -1);
}

TEST_CASE("diagnosis names the mechanism when two of its laws are not told apart", "[unit]") {
  for (uint64_t seed : {1, 2, 3}) {
    INFO("noise seed " << seed);
    testing::AnalyticForwardModel model;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {{1, 0.35}}, seed);
    std::vector<CandidateEffect> candidates = testing::AmbiguousCandidates();
    candidates[1].mechanism = "rolling resistance";  // rolling
    candidates[5].mechanism = "rolling resistance";  // roughness: another law of it
    const Diagnosis d = Diagnose(model, obs, candidates, DiagnoseOptions{});
    CHECK(d.termination == DiagnosisTermination::kEffectFound);
    REQUIRE(d.named.size() == 1);
    REQUIRE(d.named_law_alternative.size() == 1);
    const std::set<std::string> laws = {candidates[d.named[0]].key,
                                        candidates[d.named_law_alternative[0]].key};
    CHECK(laws == std::set<std::string>{"rolling", "roughness"});
    CHECK(d.not_told_apart.empty());
    CHECK(d.message.rfind("missing effect: rolling resistance, law not told apart: ", 0) == 0);
    CHECK(d.message.find("the better fit: " + candidates[d.named[0]].key) != std::string::npos);
    CHECK_FALSE(d.gap_after.gap_detected);
    // The other law is not stacked on the named one in a later step.
    for (size_t s = 1; s < d.steps.size(); ++s)
      for (const RankingEntry& e : d.steps[s].entries)
        CHECK(e.mechanism != "rolling resistance");
  }
}

}  // namespace demcal::diagnose
