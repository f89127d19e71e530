#include "diagnose/gap/gap_significance.h"

#include <catch2/catch.hpp>

#include "calibrate/analytic_models.h"

namespace demcal::diagnose {
namespace {

using calibrate::testing::Normal;

// n observations at coating levels 0..3 whose standardised residual is noise + offset + slope·w.
std::vector<Observation> Residuals(int n, uint64_t seed, double offset, double slope) {
  std::vector<Observation> obs;
  for (int i = 0; i < n; ++i) {
    const double w = i % 4;
    Observation o{"o" + std::to_string(i), i % 2 ? "angle_deg" : "heap_height_m",
                  {{"coating_PEG_wt_pct", std::to_string(w)}}, 10.0, 1.0};
    o.simulated = 10.0 + Normal(seed, i) + offset + slope * w;
    obs.push_back(o);
  }
  return obs;
}

}  // namespace

TEST_CASE("gap test: false alarms at the stated significance on a model that fits", "[unit]") {
  // 400 seeded datasets of pure noise: the rejection rate is the significance (binomial sd
  // sqrt(0.05·0.95/400) = 0.011, the band is ±3 sd).
  int rejected = 0;
  for (uint64_t seed = 1; seed <= 400; ++seed) rejected += TestGap(Residuals(20, seed, 0, 0), 0, {0.05}).gap_detected;
  CHECK(rejected / 400.0 == Approx(0.05).margin(0.033));
}

TEST_CASE("gap test detects an offset, names where, and finds the trend along the covariate", "[unit]") {
  const GapReport clean = TestGap(Residuals(24, 3, 0, 0), 1, {0.01});
  CHECK_FALSE(clean.gap_detected);
  CHECK(clean.dof == 23);
  const GapReport trend = TestGap(Residuals(24, 3, 0, 1.5), 1, {0.01});
  REQUIRE(trend.gap_detected);
  CHECK(trend.p_value < 0.01);
  CHECK_FALSE(trend.outliers.empty());  // the w = 3 rows are ~4.5 sigma off
  bool found = false;
  for (const CovariateTrend& t : trend.trends)
    if (t.covariate == "coating_PEG_wt_pct" && t.observable == "all") {
      found = true;
      CHECK(t.significant);
      CHECK(t.slope == Approx(1.5).margin(4 * t.slope_sigma));
    }
  CHECK(found);
  // An offset common to every condition: a gap, but no trend.
  const GapReport offset = TestGap(Residuals(24, 3, 2.0, 0), 1, {0.01});
  CHECK(offset.gap_detected);
  for (const CovariateTrend& t : offset.trends)
    if (t.observable == "all") CHECK_FALSE(t.significant);
}

TEST_CASE("a gap names the observable whose residuals alone trend along a covariate", "[unit]") {
  // Only the heap height grows with the coating (1 σ per level): the pooled trend over both
  // observables is half of it, the heap height's own is named in the summary; the angle's not.
  std::vector<Observation> obs = Residuals(24, 3, 0, 0);
  for (Observation& o : obs)
    if (o.observable == "heap_height_m")
      o.simulated += 1.0 * std::stod(o.condition.at("coating_PEG_wt_pct"));
  const GapReport g = TestGap(obs, 1, {0.01});
  REQUIRE(g.gap_detected);
  CHECK(g.summary.find("heap_height_m residuals trend along coating_PEG_wt_pct") !=
        std::string::npos);
  CHECK(g.summary.find("angle_deg residuals trend") == std::string::npos);
  // Within noise: no trend is named.
  CHECK(TestGap(Residuals(24, 3, 0, 0), 1, {0.01}).summary.find("trend") == std::string::npos);
}

TEST_CASE("gap options refuse a significance outside (0, 0.5)", "[unit]") {
  std::string error;
  CHECK_FALSE(GapOptions{0.7}.IsValid(&error));
  CHECK(error.find("significance") != std::string::npos);
  CHECK(GapOptions{0.01}.IsValid(&error));
}

}  // namespace demcal::diagnose
