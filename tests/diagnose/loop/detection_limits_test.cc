// The detection limits a diagnosis reports (detection_limits.h), end to end on the analytic
// stand-in (analytic_forward_model.h): an effect hidden at its reported limit is named at about
// the stated power, one hidden at a third of it hardly ever.
#include <catch2/catch.hpp>
#include <cmath>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {
namespace {

using testing::AnalyticForwardModel;

Diagnosis Run(const std::vector<std::pair<int, double>>& hidden, uint64_t seed) {
  AnalyticForwardModel model;
  model.seed = 100000 + seed;
  const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, hidden, seed);
  return Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
}

const EffectDetection* Limit(const Diagnosis& d, const std::string& key) {
  for (const EffectDetection& e : d.detection_limits)
    if (testing::Candidates()[e.candidate].key == key) return &e;
  return nullptr;
}

int NamedIn(int effect, double strength, uint64_t first_seed) {
  int named = 0;
  for (uint64_t seed = first_seed; seed < first_seed + 20; ++seed) {
    const Diagnosis d = Run({{effect, strength}}, seed);
    named += !d.named.empty() && d.named.front() == effect;
  }
  return named;
}

}  // namespace

TEST_CASE("detection limits: every open candidate but the control, said with the answer",
          "[unit]") {
  for (uint64_t seed : {1, 2, 3}) {
    INFO("noise seed " << seed);
    const Diagnosis d = Run({}, seed);
    REQUIRE(d.termination == DiagnosisTermination::kNoMissingEffect);
    CHECK(d.detection_limits.size() == 4);  // adhesion, rolling, shape, polydispersity
    CHECK(Limit(d, "control") == nullptr);
    for (const char* key : {"adhesion", "rolling", "shape", "polydispersity"}) {
      const EffectDetection* e = Limit(d, key);
      REQUIRE(e != nullptr);
      CHECK(e->has_signature);
      CHECK(std::isfinite(e->limit.magnitude));
      CHECK(e->limit.magnitude > e->limit.magnitude_half);
    }
    CHECK(d.message.find("smaller effects can hide in these data") != std::string::npos);
  }
}

TEST_CASE("detection limits: an effect hidden at its limit is named at about the power",
          "[unit]") {
  // The limit from a dataset with nothing hidden; then 20 datasets with the effect at that
  // strength. At power 0.9 fewer than 15 named has a binomial chance of about 1 %; at a third
  // of the limit the expected statistic is a third of the threshold's distance, and more than 5
  // named would say the limit overstates what the data need.
  for (int effect : {2, 3}) {  // shape and polydispersity: no gap at these strengths
    const Diagnosis none = Run({}, 1);
    const EffectDetection* e = Limit(none, testing::Candidates()[effect].key);
    REQUIRE(e != nullptr);
    const double m = e->limit.magnitude;
    const int at_limit = NamedIn(effect, m, 200);
    const int at_third = NamedIn(effect, m / 3, 300);
    INFO(testing::Candidates()[effect].key << ": limit " << m << ", named " << at_limit
                                           << " of 20 there, " << at_third << " at a third");
    CHECK(at_limit >= 15);
    CHECK(at_third <= 5);
  }
}

}  // namespace demcal::diagnose
