// TargetEvaluator on an analytic stand-in probe (no DEM): shared runs per group, parameters per
// condition and curves over a covariate reach the right model, constraints make a candidate
// infeasible without running, and a second evaluator over the same journal repeats nothing.
#include "calibrate/target_evaluator.h"

#include <catch2/catch.hpp>
#include <atomic>
#include <cmath>

#include "calibrate/synthetic_observable.h"
#include "core/io/scratch_dir.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::OneMaterialModel;

namespace {

// "angle" = 20 + 100·Γ + 50·μr and "height" = 0.01 + 0.02·μr of pair 0–0, no noise.
class LinearProbe final : public ExperimentProbe {
 public:
  mutable std::atomic<int> runs{0};
  std::string Kind() const override { return "linear"; }
  std::vector<std::string> Observables() const override { return {"angle_deg", "heap_height_m"}; }
  ProbeOutcome Run(const demcal::core::Scene& model, uint64_t) const override {
    ++runs;
    const auto& p = model.pair_parameters[0];
    return {"ok",
            {{"angle_deg", 20 + 100 * p.interfacial_energy_J_m2 + 50 * p.rolling_friction},
             {"heap_height_m", 0.01 + 0.02 * p.rolling_friction}},
            0};
  }
};

// μr (global) and Γ(w) = c0 + c1·w.
ParameterSpace CurveSpace() {
  ParameterSpace s;
  s.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0, 1, 0.1});
  s.parameters.push_back({"gamma0", PairProperty::kInterfacialEnergy, 0, 0, -1, 1, 0});
  s.parameters.push_back({"gamma_per_wt", PairProperty::kInterfacialEnergy, 0, 0, -1, 1, 0});
  s.parameters[1].curve = s.parameters[2].curve = 0;
  s.curves.push_back({"gamma(w)", PairProperty::kInterfacialEnergy, 0, 0, "w", CurveForm::kLinear, {1, 2}});
  return s;
}

std::vector<RunGroup> Groups(const ParameterSpace& space, const LinearProbe& probe) {
  std::vector<RunGroup> groups;
  for (const char* w : {"0", "2"})
    groups.push_back({std::string("heap|w=") + w, &probe, OneMaterialModel(), space, {{"w", w}}, {}});
  return groups;
}

}  // namespace

TEST_CASE("target evaluator: a curve parameter reaches each condition, one run feeds two targets",
          "[unit][calibrate]") {
  const ParameterSpace space = CurveSpace();
  LinearProbe probe;
  TargetEvaluator evaluator(space, Groups(space, probe),
                            {{0, "angle_deg"}, {1, "angle_deg"}, {1, "heap_height_m"}},
                            {.replicates = 2, .seed = 3, .workers = 2}, nullptr);
  const auto results = evaluator.EvaluateBatch({{0.2, 0.01, 0.02}, {0.4, 0.0, 0.05}});
  REQUIRE(results.size() == 2);
  REQUIRE(results[0].ok());
  CHECK(results[0].targets[0].mean == Approx(20 + 100 * 0.01 + 50 * 0.2));           // w = 0
  CHECK(results[0].targets[1].mean == Approx(20 + 100 * (0.01 + 0.02 * 2) + 50 * 0.2));  // w = 2
  CHECK(results[0].targets[2].mean == Approx(0.01 + 0.02 * 0.2));
  CHECK(results[1].targets[1].mean == Approx(20 + 100 * 0.1 + 50 * 0.4));
  CHECK(probe.runs == 2 * 2 * 2);  // candidates × groups × replicates: the height cost nothing
  CHECK(results[0].replicates_run == 4);
}

TEST_CASE("target evaluator: a curve below zero or a broken constraint is infeasible, not run",
          "[unit][calibrate]") {
  ParameterSpace space = CurveSpace();
  LinearProbe probe;
  TargetEvaluator evaluator(space, Groups(space, probe), {{0, "angle_deg"}}, {.replicates = 1}, nullptr);
  const auto negative = evaluator.EvaluateBatch({{0.2, 0.01, -0.01}});  // Γ(2) = −0.01
  CHECK_FALSE(negative[0].ok());
  CHECK_THAT(negative[0].status, Catch::Contains("infeasible") && Catch::Contains("gamma(w)"));
  space.non_decreasing = {{0, 1}};  // mu_r <= gamma0, broken below
  TargetEvaluator constrained(space, Groups(space, probe), {{0, "angle_deg"}}, {.replicates = 1}, nullptr);
  CHECK_THAT(constrained.EvaluateBatch({{0.2, 0.1, 0.0}})[0].status, Catch::Contains("non_decreasing"));
  CHECK(probe.runs == 0);
}

TEST_CASE("target evaluator: a second evaluator over the same journal repeats nothing",
          "[unit][calibrate]") {
  demcal::testing::ScratchDir dir("target_evaluator_journal");
  const ParameterSpace space = CurveSpace();
  LinearProbe probe;
  std::string error;
  std::vector<CandidateResult> first;
  {
    EvaluationJournal journal;
    REQUIRE(journal.Open(dir.str("journal.jsonl"), "f", &error, 3));
    TargetEvaluator e(space, Groups(space, probe), {{0, "angle_deg"}, {1, "heap_height_m"}},
                      {.replicates = 2}, &journal);
    first = e.EvaluateBatch({{0.2, 0.01, 0.02}});
  }
  const int runs = probe.runs;
  EvaluationJournal journal;
  REQUIRE(journal.Open(dir.str("journal.jsonl"), "f", &error, 3));
  CHECK(journal.LoadedRecords() == 4);
  TargetEvaluator again(space, Groups(space, probe), {{0, "angle_deg"}, {1, "heap_height_m"}},
                        {.replicates = 2}, &journal);
  const auto second = again.EvaluateBatch({{0.2, 0.01, 0.02}});
  CHECK(probe.runs == runs);
  CHECK(second[0].replicates_reused == 4);
  CHECK(second[0].targets[1].mean == first[0].targets[1].mean);  // bit-identical from the journal
}

namespace {

// "angle" = 30 + a noise that depends on the seed and on μr (so spreads differ by candidate).
class NoisyProbe final : public ExperimentProbe {
 public:
  std::string Kind() const override { return "noisy"; }
  std::vector<std::string> Observables() const override { return {"angle_deg"}; }
  ProbeOutcome Run(const demcal::core::Scene& model, uint64_t seed) const override {
    const double mu = model.pair_parameters[0].rolling_friction;
    return {"ok", {{"angle_deg", 30 + std::sin(1e3 * mu + static_cast<double>(seed % 1000))}}, 0};
  }
};

}  // namespace

TEST_CASE("target evaluator: the sem comes from the replicate spread pooled over candidates",
          "[unit][calibrate]") {
  ParameterSpace space;
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0, 1, 0.1});
  NoisyProbe probe;
  std::vector<RunGroup> groups{{"g", &probe, OneMaterialModel(), space, {}, {}}};
  const std::vector<std::vector<double>> candidates{{0.1}, {0.2}, {0.3}};
  TargetEvaluator pooled(space, groups, {{0, "angle_deg"}}, {.replicates = 2, .seed = 5}, nullptr);
  TargetEvaluator single(space, groups, {{0, "angle_deg"}},
                         {.replicates = 2, .seed = 5, .pool_spread = false}, nullptr);
  const auto p = pooled.EvaluateBatch(candidates), s = single.EvaluateBatch(candidates);
  double variance = 0;  // Σ s_i² / k with s_i² = 2·sem_i² for two replicates
  for (const CandidateResult& r : s) variance += 2 * r.targets[0].sem * r.targets[0].sem / 3;
  for (size_t c = 0; c < 3; ++c) {
    CHECK(p[c].targets[0].mean == s[c].targets[0].mean);
    CHECK(p[c].targets[0].sem == Approx(std::sqrt(variance / 2)));
  }
  CHECK(s[0].targets[0].sem != Approx(s[1].targets[0].sem));  // the single spreads do differ
}
