// LinearisedBaseStep (diagnose/loop/base_step.h) and the check of a stagnated base with it
// (SettleBase, base_fit.h).
#include "diagnose/loop/base_step.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/base_fit.h"
#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {
namespace {

// Observations of a linear model y = a + J u_true (σ 1 each, no simulation noise), predicted at u.
std::vector<Observation> LinearAt(const std::vector<std::vector<double>>& J,
                                  const std::vector<double>& u_true, const std::vector<double>& u) {
  std::vector<Observation> at;
  for (size_t i = 0; i < J.size(); ++i) {
    Observation o;
    for (size_t j = 0; j < u.size(); ++j) {
      o.measured += J[i][j] * u_true[j];
      o.simulated += J[i][j] * u[j];
    }
    at.push_back(o);
  }
  return at;
}

}  // namespace

TEST_CASE("the linearised base step reaches the least-squares point of a linear model", "[unit]") {
  const std::vector<std::vector<double>> J{{10, 2}, {3, -8}, {5, 5}};
  const std::vector<double> truth{0.4, 0.55}, start{0.9, 0.1};
  const BaseStep s = LinearisedBaseStep(LinearAt(J, truth, start), start, J, {});
  REQUIRE(s.ok);
  CHECK(s.unit[0] == Approx(0.4).margin(1e-12));
  CHECK(s.unit[1] == Approx(0.55).margin(1e-12));
  CHECK(s.chi2_now > 10);
  CHECK(s.chi2_predicted == Approx(0).margin(1e-18));
}

TEST_CASE("the linearised base step stops on a bound and solves the rest", "[unit]") {
  // The truth lies beyond the upper bound in u0: u0 is held at 1 and u1 re-solved against what
  // that leaves (here u1's own column is independent of u0's: it goes to its truth).
  const std::vector<std::vector<double>> J{{10, 0}, {0, 4}, {2, 0}};
  const std::vector<double> truth{1.3, 0.2}, start{0.5, 0.5};
  const BaseStep s = LinearisedBaseStep(LinearAt(J, truth, start), start, J, {});
  REQUIRE(s.ok);
  CHECK(s.unit[0] == 1.0);
  CHECK(s.unit[1] == Approx(0.2).margin(1e-12));
  // What is left is the part of the gap beyond the bound: 0.3 in u0, over both of its rows.
  CHECK(s.chi2_predicted == Approx(0.09 * (100 + 4)).epsilon(1e-9));
}

TEST_CASE("the linearised base step does not move along a direction the runs do not resolve",
          "[unit]") {
  // u1's sensitivities are within their own standard errors (JacobianNoiseFloor): no step in it.
  // (Its column is orthogonal to u0's, so the singular directions are the two axes.)
  const std::vector<std::vector<double>> J{{3, 0.4}, {10, -0.12}},
      J_sigma{{0.1, 2}, {0.1, 2}};
  const std::vector<double> truth{0.4, 0.9}, start{0.6, 0.3};
  const BaseStep s = LinearisedBaseStep(LinearAt(J, truth, start), start, J, J_sigma);
  REQUIRE(s.ok);
  CHECK(s.unit[1] == Approx(0.3).margin(1e-12));
  CHECK(s.unit[0] == Approx(0.4).margin(1e-12));  // u0's own direction: to its truth
}

TEST_CASE("a base that stagnated off its optimum is moved there by its own linearised step",
          "[unit]") {
  // Every unsettled round of the stand-in's search stops at u 0.7 (μ 0.76) while the data were
  // made at μ 0.6 (u 0.5), nothing hidden: twice the budget finds the same point, so the fit
  // counts as settled by stagnation, with a gap its own parameter would close. Its
  // sensitivities predict that drop, a simulation confirms it, and the base moves.
  for (uint64_t seed : {1, 2, 3}) {
    INFO("noise seed " << seed);
    testing::AnalyticForwardModel model;
    model.settle_at_scale = 1000;
    model.stall_shift = 0.3;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.6, {}, seed);
    const BaseFit b = SettleBase(model, obs, 1.0, 0.01, {});
    CHECK(b.stagnated);
    REQUIRE_FALSE(b.steps.empty());
    CHECK(b.steps[0].accepted);
    CHECK(b.steps[0].chi2_simulated < b.steps[0].chi2_before);
    CHECK(std::abs(b.base.base_unit[0] - 0.5) < 0.03);
    CHECK(b.summary.find("the base moved there") != std::string::npos);
    // The diagnosis on it: nothing hidden, nothing named.
    testing::AnalyticForwardModel again;
    again.settle_at_scale = 1000;
    again.stall_shift = 0.3;
    const Diagnosis d = Diagnose(again, obs, testing::Candidates(), DiagnoseOptions{});
    CHECK(d.termination == DiagnosisTermination::kNoMissingEffect);
    CHECK(d.named.empty());
  }
}

TEST_CASE("a step from a stagnated base goes only to the data's least-squares point", "[unit]") {
  // The stand-in's search stops at u 0.5, where the data were made; their least-squares point
  // differs by the measurement noise. A step is simulated only where the linearisation predicts
  // a drop above BaseStepThreshold, and then lands on that point (the stand-in is linear in u);
  // the base never moves away from it.
  int stepped = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    INFO("noise seed " << seed);
    testing::AnalyticForwardModel model;
    model.settle_at_scale = 1000;
    model.stall_shift = 0.5;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.6, {}, seed);
    testing::AnalyticForwardModel grid;  // settles at once, on the least-squares grid point
    grid.measured = model.measured;
    const double u_ls = SettleBase(grid, obs, 1.0, 0.01, {}, true).base.base_unit[0];
    const BaseFit b = SettleBase(model, obs, 1.0, 0.01, {}, true);
    CHECK(b.stagnated);
    const double u = b.base.base_unit[0];
    if (b.steps.empty()) {
      CHECK(u == 0.5);
      continue;
    }
    ++stepped;
    CHECK(b.steps[0].chi2_before - b.steps[0].chi2_predicted > b.steps[0].threshold);
    CHECK(b.steps[0].accepted);
    CHECK(std::abs(u - u_ls) <= 1e-3 + 1e-9);  // the grid's spacing
  }
  CHECK(stepped < 40);  // most stops lie within the threshold of their least-squares point
}

TEST_CASE("the step threshold: one parameter's sd, or the noise's share of the drop", "[unit]") {
  CHECK(BaseStepThreshold(1, 0, 0.01) == 1.0);    // noise-free: the profile-likelihood unit
  CHECK(BaseStepThreshold(1, 1, 0.01) == Approx(6.635).epsilon(1e-3));  // χ²_1 at 99 %
  CHECK(BaseStepThreshold(2, 0.5, 0.01) == Approx(0.25 * 9.210).epsilon(1e-3));
}

}  // namespace demcal::diagnose
