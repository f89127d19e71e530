// The screen without a gap (diagnosis.h step 2; docs/diagnose/ranking.md, "The screen without a
// gap"), on the analytic stand-in (analytic_forward_model.h).
#include <catch2/catch.hpp>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {
namespace {

using testing::AnalyticForwardModel;

// One dataset: μ 0.5 with `hidden`, measurement noise `seed`, and the simulation's own noise
// drawn per dataset too (its common-random-number offset), diagnosed with or without the screen.
Diagnosis Run(const std::vector<std::pair<int, double>>& hidden, uint64_t seed, bool screen,
              double mu = 0.5) {
  AnalyticForwardModel model;
  model.seed = 100000 + seed;
  const std::vector<Observation> obs = testing::MakeObservations(&model, mu, hidden, seed);
  DiagnoseOptions o;
  o.screen = screen;
  return Diagnose(model, obs, testing::Candidates(), o);
}

std::string Named(const Diagnosis& d) {
  return d.named.empty() ? "" : testing::Candidates()[d.named.front()].key;
}

}  // namespace

TEST_CASE("the screen names a weak effect that the omnibus gap test does not flag", "[unit]") {
  // Shape at 0.15 and polydispersity at 0.3: the omnibus χ² (8 degrees of freedom at α/2, and
  // the coating trend at α/2) misses them in 16 and 17 of 20 datasets; each effect's own refit
  // (1 degree of freedom at α/5) names it in 12 and 11 of those. Without the screen every one of
  // them ends at "no missing effect".
  for (const auto& [name, hidden] : std::vector<std::pair<std::string, std::pair<int, double>>>{
           {"shape", {2, 0.15}}, {"polydispersity", {3, 0.3}}}) {
    int screened = 0, named = 0;
    for (uint64_t seed = 1; seed <= 20; ++seed) {
      INFO(name << ", noise seed " << seed);
      const Diagnosis d = Run({hidden}, seed, true);
      if (d.gap_before.gap_detected) continue;
      ++screened;
      CHECK(d.screened);
      CHECK((Named(d).empty() || Named(d) == name));  // never a wrong effect
      if (Named(d) != name) continue;
      ++named;
      CHECK(d.termination == DiagnosisTermination::kEffectFound);
      CHECK(d.message.find("found by its own directed test") != std::string::npos);
      CHECK(d.message.find("the omnibus gap test did not flag") != std::string::npos);
      const Diagnosis off = Run({hidden}, seed, false);
      CHECK(off.termination == DiagnosisTermination::kNoMissingEffect);
      CHECK(off.steps.empty());
    }
    INFO(name << ": named in " << named << " of " << screened << " datasets without a gap");
    CHECK(screened >= 10);
    CHECK(named * 2 >= screened);
  }
}

TEST_CASE("a control first in the screen leaves no missing effect", "[unit]") {
  // Shape flagged as a copy of a fitted parameter (a control) and hidden weakly: where the
  // screen's best refit is that control, nothing is named and, without a gap, no model-form
  // offset is claimed either.
  std::vector<CandidateEffect> candidates = testing::Candidates();
  candidates[2].control = true;
  int control_first = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    INFO("noise seed " << seed);
    AnalyticForwardModel model;
    model.seed = 100000 + seed;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {{2, 0.15}}, seed);
    const Diagnosis d = Diagnose(model, obs, candidates, DiagnoseOptions{});
    if (!d.screened) continue;
    CHECK(d.named.empty());
    if (!d.steps[0].ranking.control_first) continue;
    ++control_first;
    CHECK(d.termination == DiagnosisTermination::kNoMissingEffect);
    CHECK(d.message.find("a control (a copy of a fitted parameter) ranks first") !=
          std::string::npos);
  }
  CHECK(control_first >= 3);
}

TEST_CASE("the screen's false alarms on a correct model stay within alpha", "[unit]") {
  // Nothing hidden. Every answer the screen can change rests on one candidate's own test at
  // α/K (K = 5 here), so P(any) ≤ K·α/K = α by the union bound, whatever the gate before it
  // and however the candidates' tests correlate. Over N = 500 datasets at α = 0.01 the count
  // is Binomial(500, ≤ 0.01): P(count ≥ 12) = 0.0052, so a count above 11 rejects "rate ≤ α" at
  // the 1 % level (one-sided exact binomial tail).
  const int n = 500;
  int named = 0, changed = 0, screened = 0;
  for (uint64_t seed = 1; seed <= n; ++seed) {
    const Diagnosis d = Run({}, seed, true);
    screened += d.screened;
    named += !d.named.empty();
    changed += d.screened && d.termination != DiagnosisTermination::kNoMissingEffect;
  }
  INFO(named << " named and " << changed << " screened answers changed in " << n
              << " datasets, " << screened << " screened");
  CHECK(screened >= n * 9 / 10);  // the gap test at α flags few: the screen did run
  CHECK(named <= 11);
  CHECK(changed <= 11);
}

TEST_CASE("a case with a gap, or a base on a bound, runs as without the screen", "[unit]") {
  // The screen runs only without a gap, on a settled base inside its range: everything else
  // (every step, every simulation, the answer) is the same with it off.
  const std::vector<std::pair<int, double>> gap_cases = {{0, 0.08}, {2, 0.8}, {3, 0.9}};
  for (const auto& hidden : gap_cases)
    for (uint64_t seed : {1, 2}) {
      INFO("hidden " << hidden.first << " noise seed " << seed);
      const Diagnosis on = Run({hidden}, seed, true), off = Run({hidden}, seed, false);
      REQUIRE(on.gap_before.gap_detected);
      CHECK_FALSE(on.screened);
      CHECK(on.termination == off.termination);
      CHECK(on.message == off.message);
      CHECK(on.named == off.named);
      CHECK(on.simulations == off.simulations);
    }
  // μ 0.19, below the range [0.2, 1]: the base ends on its bound within noise; the bound probe
  // (bound_step.h) runs its one step, the screen does not add another.
  for (uint64_t seed : {1, 2, 3}) {
    INFO("base on a bound, noise seed " << seed);
    const Diagnosis on = Run({}, seed, true, 0.19), off = Run({}, seed, false, 0.19);
    REQUIRE_FALSE(on.base_at_bound.empty());
    CHECK_FALSE(on.screened);
    CHECK(on.steps.size() == 1);
    CHECK(on.termination == off.termination);
    CHECK(on.message == off.message);
    CHECK(on.simulations == off.simulations);
  }
}

}  // namespace demcal::diagnose
