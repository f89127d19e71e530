// "After" for a "not told apart" answer (diagnosis.h, docs/diagnose/ranking.md): the answer
// offers either tied effect, so χ²/dof after is the gap test at the worse of the two tied
// refits, each one's given beside it, and not the base's (which the answer would otherwise
// repeat as if nothing closed the gap). Stand-in: the analytic model's "rolling" hidden, and
// "roughness", whose signature agrees with it within a few per cent, in the library.
#include <algorithm>
#include <catch2/catch.hpp>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {

TEST_CASE("a 'not told apart' answer's after is the worse of the two tied refits", "[unit]") {
  for (uint64_t seed : {1, 2, 3}) {
    INFO("noise seed " << seed);
    testing::AnalyticForwardModel model;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {{1, 0.35}}, seed);
    const std::vector<CandidateEffect> candidates = testing::AmbiguousCandidates();
    const Diagnosis d = Diagnose(model, obs, candidates, DiagnoseOptions{});
    REQUIRE(d.termination == DiagnosisTermination::kNotToldApart);
    CHECK(d.after_tied);
    CHECK_FALSE(d.after_revalued);
    REQUIRE(d.tied_chi2_per_dof_after.size() == 2);
    const double worse = std::max(d.tied_chi2_per_dof_after[0], d.tied_chi2_per_dof_after[1]);
    CHECK(d.gap_after.chi2_per_dof == Approx(worse));
    // Either effect closes the gap the base leaves: after is below before.
    CHECK(d.gap_after.chi2_per_dof < 0.5 * d.gap_before.chi2_per_dof);
    CHECK(d.fitted_parameters_after == 2);  // μs and the tied effect's parameter
    // Each tied value is that refit's χ²/dof as the ranking saw it (same rows, its own sem).
    const DiagnosisStep& step = d.steps.back();
    const RankingEntry& first = step.entries[step.ranking.winner];
    const RankingEntry& second = step.entries[step.ranking.tied];
    CHECK(d.tied_chi2_per_dof_after[0] == Approx(first.chi2_per_dof).epsilon(0.1));
    CHECK(d.tied_chi2_per_dof_after[1] == Approx(second.chi2_per_dof).epsilon(0.1));
    CHECK(d.message.find("with either effect the gap is chi2/dof ") != std::string::npos);
  }
}

}  // namespace demcal::diagnose
