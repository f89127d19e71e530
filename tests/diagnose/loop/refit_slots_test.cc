#include <catch2/catch.hpp>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {

TEST_CASE("a simulated refit that falls short of its linear promise passes its slot on", "[unit]") {
  // A decoy whose signature at its probe (0.1) is the hidden shape's plus a little of the hidden
  // adhesion's, so its linearised refit fits best, but whose response stops at the probe: its
  // simulated refit explains nothing. With one refit slot, the decoy takes it; the slot then
  // passes to the next linearised candidate, the shape, which is named. Without the hand-over
  // the step had one failed refit and no winner (model-form offset), as the DEM `wide_psd` twin
  // had after the clump lever change (docs/diagnose/results.md).
  std::vector<CandidateEffect> candidates = testing::AmbiguousCandidates();
  candidates.push_back({"decoy", "", {{"t", "", 0, 2, 0.1}}});  // EffectChange case 6
  for (uint64_t seed : {1, 2, 3}) {
    INFO("noise seed " << seed);
    testing::AnalyticForwardModel model;
    const std::vector<Observation> obs =
        testing::MakeObservations(&model, 0.5, {{2, 0.8}, {0, 0.016}}, seed);
    DiagnoseOptions o;
    o.dem_refits = 1;
    const Diagnosis d = Diagnose(model, obs, candidates, o);
    REQUIRE_FALSE(d.steps.empty());
    REQUIRE_FALSE(d.named.empty());
    CHECK(candidates[d.named[0]].key == "shape");
    for (int c : d.named) CHECK(candidates[c].key != "decoy");
    // The premise: the decoy led the linearised ranking (with one slot, only the first is
    // simulated unless it fails), was simulated, and failed.
    for (const RankingEntry& e : d.steps[0].entries)
      if (e.key == "decoy") {
        CHECK(e.simulated);
        CHECK_FALSE(e.evidence.significant);
      }
  }
}

}  // namespace demcal::diagnose
