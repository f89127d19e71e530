#include "diagnose/loop/base_noise.h"

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>

#include "diagnose/analytic_forward_model.h"
#include "diagnose/loop/base_fit.h"
#include "diagnose/loop/diagnosis.h"
#include "diagnose/loop/fit_state.h"
#include "diagnose/ranking/evidence.h"

namespace demcal::diagnose {
namespace {

using testing::AnalyticForwardModel;

Observation Row(double simulated, double sem, double scatter, double measured, int source) {
  Observation o;
  o.measured = measured;
  o.uncertainty = 1;
  o.simulated = simulated;
  o.sem = sem;
  o.scatter = scatter;
  o.source = source;
  return o;
}

// The stand-in's base at unit u with another packing (seed) of the same scenes.
Prediction Packing(AnalyticForwardModel& model, double u, uint64_t seed) {
  const uint64_t common = model.seed;
  model.seed = seed;
  const Prediction p = model.Evaluate({{{u}, {}}})[0];
  model.seed = common;
  return p;
}

}  // namespace

TEST_CASE("base chi2 noise: rows reading one simulated mean add before squaring", "[unit]") {
  // Three rows read one simulated mean (2 ± 0.5, measured 0; one source): one error moves all
  // three terms. r = 2/√1.25, u = 0.5/√1.25: each term 2·r·u = 1.6; together sd 4.8, not √3·1.6.
  const std::vector<Observation> shared = {Row(2, 0.5, 1, 0, 7), Row(2, 0.5, 1, 0, 7),
                                           Row(2, 0.5, 1, 0, 7)};
  CHECK(BaseChi2(shared).chi2 == Approx(3 * 4 / 1.25));
  CHECK(BaseChi2(shared).noise_sd == Approx(4.8));
  // The same numbers from three scenes (three sources): independent, however alike they are.
  const std::vector<Observation> own = {Row(2, 0.5, 1, 0, 0), Row(2, 0.5, 1, 0, 1),
                                        Row(2, 0.5, 1, 0, -1)};
  CHECK(BaseChi2(own).noise_sd == Approx(1.6 * std::sqrt(3.0)));
  // One source read by rows it misses in opposite directions: their terms cancel.
  const std::vector<Observation> opposite = {Row(2, 0.5, 1, 0, 3), Row(2, 0.5, 1, 4, 3)};
  CHECK(BaseChi2(opposite).noise_sd == Approx(0).margin(1e-12));
  // No simulation noise: none in χ².
  CHECK(BaseChi2({Row(2, 0, 0, 0, 0)}).noise_sd == 0);
}

TEST_CASE("base chi2 noise matches the scatter of chi2 over packings of shared scenes", "[unit]") {
  // The analytic stand-in with one simulated heap per kind read by all three coating rows (a base
  // whose coating changes nothing, run once per scene), fitted off the truth (μ 0.68 for 0.6):
  // the three rows of a kind miss in one direction. χ² over 4000 packings of the same point has
  // an sd that BaseChi2 predicts from one packing's residuals and standard errors; the rows
  // counted as independent (Chi2NoiseSd) fall short by about √3 on the angle rows.
  AnalyticForwardModel model;
  model.shared_scenes = true;
  const std::vector<Observation> obs = testing::MakeObservations(&model, 0.6, {}, 3);
  const double u = (0.68 - 0.2) / 0.8;
  double sum = 0, sum2 = 0, predicted = 0, independent = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    const std::vector<Observation> at = WithPrediction(obs, Packing(model, u, 5000 + k), 1.0);
    const NoisyChi2 c = BaseChi2(at);
    sum += c.chi2, sum2 += c.chi2 * c.chi2, predicted += c.noise_sd / n;
    Eigen::VectorXd r(at.size()), su(at.size());
    for (size_t i = 0; i < at.size(); ++i) r(i) = at[i].Residual(), su(i) = at[i].sem / at[i].Sigma();
    independent += Chi2NoiseSd(r, su, Eigen::VectorXd::Zero(r.size()), 0) / n;
  }
  const double empirical = std::sqrt(sum2 / n - (sum / n) * (sum / n));
  INFO("empirical sd " << empirical << ", BaseChi2 " << predicted << ", independent " << independent);
  CHECK(predicted == Approx(empirical).epsilon(0.15));
  CHECK(independent < 0.75 * empirical);
}

TEST_CASE("a base sensitivity within its own noise is reported undetermined", "[unit]") {
  // The base sensitivities resolve μ (χ² moves by far more than 12 over the range) but are
  // reported with standard errors twice their size: the identifiability counts them as not
  // resolved above the noise (JacobianNoiseFloor) and the verdict says so first.
  for (double noise : {0.0, 2.0}) {
    AnalyticForwardModel model;
    model.sensitivity_noise = noise;
    const std::vector<Observation> obs = testing::MakeObservations(&model, 0.5, {{2, 0.8}}, 1);
    const BaseFit b = SettleBase(model, obs, 1.0, 0.01, {});
    CHECK(b.identifiability.Identifiable() == (noise == 0));
    const Diagnosis d = Diagnose(model, obs, testing::Candidates(), DiagnoseOptions{});
    CHECK((d.message.rfind("the data do not determine the base parameters", 0) == 0) == (noise > 0));
  }
}

TEST_CASE("base chi2 noise: two observables of one run by their correlation", "[unit]") {
  // The angle and the height of one heap (two sources of one run), their errors correlated
  // +0.6 (Prediction::correlation, pooled from the replicates: replicate_pool.h), carried to the
  // observations by WithPrediction: var = a1² + a2² + 2·0.6·a1·a2, a_i = 2 r_i u_i.
  std::vector<Observation> rows = {Row(12, 0.5, 1, 10, 0), Row(0.013, 0.0004, 0.001, 0.012, 1)};
  rows[1].uncertainty = 0.0005;
  Prediction p;
  for (const Observation& o : rows) {
    p.mean.push_back(o.simulated), p.sem.push_back(o.sem), p.spread.push_back(o.scatter);
    p.source.push_back(o.source);
  }
  p.correlation = {{1, 0.6}, {0.6, 1}};
  const std::vector<Observation> at = WithPrediction(rows, p, 0);
  const double a1 = 2 * at[0].Residual() * at[0].sem / at[0].Sigma();
  const double a2 = 2 * at[1].Residual() * at[1].sem / at[1].Sigma();
  CHECK(BaseChi2(at).noise_sd == Approx(std::sqrt(a1 * a1 + a2 * a2 + 1.2 * a1 * a2)));
  p.correlation.clear();  // the sources alone: independent
  CHECK(BaseChi2(WithPrediction(rows, p, 0)).noise_sd == Approx(std::hypot(a1, a2)));
}

}  // namespace demcal::diagnose
