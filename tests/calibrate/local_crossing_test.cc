// The crossing of a noisy observable from a straight line through the candidates around it
// (calibrate/local_crossing.h): exact on a line, its σ honest on noisy lines, and refused where
// a line does not describe the candidates. The analytic reference is weighted least squares on
// a straight line (e.g. Press et al., Numerical Recipes 3rd ed. §15.2): with a centred abscissa,
// var α = 1/Σw and var β = 1/Σw(u − ū)².
#include "calibrate/local_crossing.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "calibrate/calibration.h"
#include "tests/calibrate/analytic_models.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::LinearTargets;
using demcal::calibrate::testing::Normal;

namespace {

Sample At(double u, double r, double noise) { return {{u}, {true, {r}, {noise}}}; }

}  // namespace

TEST_CASE("local crossing: a line's root, from the candidates around it", "[unit][calibrate]") {
  // r = 5 (u − 0.4): the sign changes between 0.35 and 0.5; a line fits all five candidates.
  std::vector<Sample> s;
  for (double u : {0.9, 0.1, 0.35, 0.5, 0.3}) s.push_back(At(u, 5 * (u - 0.4), 0.1));
  s.push_back({{0.45}, {false, {}, {}}});  // a failed candidate is left out
  const LocalCrossing c = FitLocalCrossing(s);
  INFO(c.message);
  REQUIRE(c.fitted);
  CHECK(c.matched);
  CHECK(c.points == 5);
  CHECK(c.window_min == 0.1);
  CHECK(c.window_max == 0.9);
  CHECK(c.unit == Approx(0.4).margin(1e-12));
  CHECK(c.slope == Approx(5).epsilon(1e-12));
  CHECK(c.chi_square == Approx(0).margin(1e-20));
  CHECK(c.dof == 3);
  // Equal weights w = 1/(0.1² + 0.01²) on 0.1, 0.3, 0.35, 0.5, 0.9: ū = 0.43, Σ(u − ū)² = 0.358.
  const double w = 1 / (0.01 + 1e-4), d = 0.4 - 0.43;
  const double var_r = 1 / (5 * w) + d * d / (0.358 * w);
  CHECK(c.residual_sigma == Approx(std::sqrt(var_r)).epsilon(1e-9));
  // The crossing moves with the line and with the measurement (variance 1, standardised).
  CHECK(c.unit_sigma == Approx(std::sqrt(1 + var_r) / 5).epsilon(1e-9));
}

TEST_CASE("local crossing: its standard error covers the root as often as it says",
          "[unit][calibrate]") {
  // r = 50 (u − 0.5) + N(0, 3²) − m at eight candidates 0.395 ... 0.605, m ~ N(0, 1) the
  // measurement's own error (standardised): each candidate three times as noisy as the
  // measurement, so none matches alone, the line's change over the eight six times the noise (a
  // slope the fit resolves in most draws). σ_u counts the line and the measurement. Over 2,000 draws the 1σ interval
  // u* ± σ_u must hold the root 68 % of the time. The covariance is scaled by max(1, χ²/dof),
  // which only widens it, so coverage at or above 68 % is honest and well below it is not; the
  // delta method's σ_u and the window's selection (it depends on the draw) make it approximate.
  // Binomial standard error of a fraction near 0.7 over ~2,000 fits: 0.01.
  int fitted = 0, covered = 0, matched = 0;
  for (int draw = 0; draw < 2000; ++draw) {
    std::vector<Sample> s;
    const double m = Normal(78, draw);
    for (int k = 0; k < 8; ++k) {
      const double u = 0.395 + 0.03 * k;
      s.push_back(At(u, 50 * (u - 0.5) + 3 * Normal(77, draw * 8 + k) - m, 3));
    }
    const LocalCrossing c = FitLocalCrossing(s);
    if (!c.fitted) continue;
    ++fitted;
    covered += std::abs(c.unit - 0.5) <= c.unit_sigma;
    matched += c.matched;
  }
  INFO(fitted << " fitted, " << covered << " covered, " << matched << " matched");
  CHECK(fitted > 1000);
  const double coverage = static_cast<double>(covered) / fitted;
  CHECK(coverage > 0.64);  // 68 % less 4 binomial standard errors
  CHECK(coverage < 0.90);  // and not so wide that it says nothing
  // A line through 4-8 candidates of noise 3 has a standard error of 1.1-1.5 at the crossing:
  // rarely as precise as the measurement.
  CHECK(matched < fitted / 2);
}

TEST_CASE("local crossing: refused where a line does not tell the crossing",
          "[unit][calibrate]") {
  SECTION("no sign change: the measurement is not bracketed") {
    const LocalCrossing c = FitLocalCrossing({At(0.1, -3, 0.5), At(0.5, -1, 0.5), At(0.9, -2, 0.5)});
    CHECK_FALSE(c.fitted);
    CHECK(c.message.find("either side") != std::string::npos);
  }
  SECTION("two candidates only: a line through them cannot be tested") {
    const LocalCrossing c = FitLocalCrossing({At(0.2, -1, 0.5), At(0.6, 1, 0.5)});
    CHECK_FALSE(c.fitted);
    CHECK(c.points == 2);
  }
  SECTION("a bend: the far candidates leave the window") {
    // r = 5 (u − 0.4) up to 0.6, then flat at 1: the line through all misfits; without the
    // candidates past the bend it fits again, and the crossing stays exact.
    std::vector<Sample> s;
    for (double u : {0.2, 0.3, 0.38, 0.45, 0.55, 0.8, 0.9, 1.0})
      s.push_back(At(u, u <= 0.6 ? 5 * (u - 0.4) : 1.0, 0.1));
    const LocalCrossing c = FitLocalCrossing(s);
    INFO(c.message);
    REQUIRE(c.fitted);
    CHECK(c.window_max == 0.55);
    CHECK(c.unit == Approx(0.4).margin(1e-12));
  }
  SECTION("a jump: the line misfits its candidates") {
    // r = −3 below 0.5 and +3 above, each to 0.1: χ² far beyond the 1 % level.
    std::vector<Sample> s;
    for (double u : {0.3, 0.4, 0.45, 0.55, 0.6, 0.7}) s.push_back(At(u, u < 0.5 ? -3 : 3, 0.1));
    const LocalCrossing c = FitLocalCrossing(s);
    CHECK_FALSE(c.fitted);
    CHECK(c.message.find("misfits") != std::string::npos);
  }
  SECTION("noise far above the slope: the slope is not resolved") {
    const LocalCrossing c = FitLocalCrossing(
        {At(0.40, -0.5, 3), At(0.45, 0.4, 3), At(0.50, -0.3, 3), At(0.55, 0.6, 3)});
    CHECK_FALSE(c.fitted);
    CHECK(c.message.find("not resolved") != std::string::npos);
  }
}

TEST_CASE("local crossing in a calibration: a noisy bracket search that matched no candidate",
          "[unit][calibrate]") {
  // angle = 15 + 60 μr, each candidate's own noise (independent runs) with sem 2.5 against a
  // measurement of 33 ± 1 (μr = 0.3): no candidate can match (sem > u, and the driver cannot add
  // replicates here), so the bracket ends on its budget. The summary carries the line's
  // crossing, which must lie within 3 of its σ of the truth for every seed tried.
  ParameterSpace space;
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 0, 0.0, 1.0, 0.1});
  CalibrationOptions o;
  o.optimiser_options.max_evaluations = 10;
  int fitted = 0;
  for (uint64_t seed : {1, 2, 3, 4, 5}) {
    LinearTargets m;
    m.offset = {15}, m.slope = {{60}}, m.sem = {2.5}, m.seed = seed, m.independent_noise = true;
    const CalibrationSummary s = Calibrate(m, space, {{"angle", "angle_deg", 33, 1, "twin"}}, o);
    INFO("seed " << seed << "\n" << s.BriefReport(space) << s.local_crossing.message);
    REQUIRE(s.termination != Termination::kWithinNoise);
    if (!s.local_crossing.fitted) continue;  // the draw left no testable line: nothing claimed
    ++fitted;
    CHECK(std::abs(s.local_crossing_value - 0.3) <= 3 * s.local_crossing_sigma);
    CHECK(s.local_crossing_sigma == Approx(s.local_crossing.unit_sigma));  // unit = SI here
  }
  CHECK(fitted >= 3);  // the search leaves a line to fit in most draws (the test is not vacuous)
}
