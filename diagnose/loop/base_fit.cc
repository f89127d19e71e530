#include "diagnose/loop/base_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibrate/chi_square.h"
#include "calibrate/jacobian_svd.h"
#include "core/math/number_text.h"
#include "diagnose/gap/gap_significance.h"
#include "diagnose/loop/fit_state.h"
#include "diagnose/loop/base_noise.h"
#include "diagnose/loop/base_step.h"
#include "diagnose/ranking/evidence.h"

namespace demcal::diagnose {

bool SettledTermination(const std::string& termination) {
  return termination == "within_noise" || termination == "converged" ||
         termination == "out_of_range";
}

namespace {

NoisyChi2 Chi2(const std::vector<Observation>& observations, const Prediction& p,
               double floor_factor) {
  if (!p.ok) return {};
  return BaseChi2(WithPrediction(observations, p, floor_factor));
}

// χ² figures in the summary: 3 significant digits.
std::string Rounded(double x) { return core::NumberText(x, 3); }

// On a bound: the unit coordinate at 0 or 1 up to rounding (optimisers clamp to the bound
// exactly; 1e-9 only absorbs the unit map's arithmetic, it is not a tolerance on the fit).
bool AtBound(double u) { return u <= 1e-9 || u >= 1 - 1e-9; }

bool WithinNoise(const std::vector<Observation>& observations, const BaseCalibration& base,
                 double floor_factor, double significance) {
  return base.prediction.ok &&
         !TestGap(WithPrediction(observations, base.prediction, floor_factor),
                  static_cast<int>(base.base_unit.size()), {significance})
              .gap_detected;
}

// A base settled by stagnation, checked by its own linearised step (base_fit.h): moves b's base
// to a simulated step point with a lower χ², and records every step simulated.
void CheckStagnatedOptimum(ForwardModel& model, const std::vector<Observation>& observations,
                           double floor_factor, double significance, BaseFit* b) {
  int simulated = 0;
  while (simulated < kMaxBaseSteps) {
    const BaseStep step =
        LinearisedBaseStep(WithPrediction(observations, b->base.prediction, floor_factor),
                           b->base.base_unit, b->base.jacobian, b->base.jacobian_sigma);
    const double chi2_now = step.chi2_now;  // BaseChi2's χ², the same Σ r²
    const double threshold =
        BaseStepThreshold(step.rank, step.max_noise_per_sigma, significance);
    if (!step.ok || chi2_now - step.chi2_predicted <= threshold)
      return;  // the linearisation sees no drop beyond noise: the stagnated fit stands
    bool moved = false;
    for (const double fraction : {1.0, 0.5}) {  // the whole step, then half (a damped retry)
      if (simulated >= kMaxBaseSteps) break;
      BaseStepRecord r{PartWay(b->base.base_unit, step.unit, fraction), fraction, chi2_now};
      r.chi2_predicted = step.chi2_predicted;
      r.threshold = threshold;
      const Prediction p = model.Evaluate({ModelPoint{r.unit, {}}}).at(0);
      ++simulated;
      r.chi2_simulated = Chi2(observations, p, floor_factor).chi2;
      r.accepted = p.ok && r.chi2_simulated < chi2_now;
      b->steps.push_back(r);
      if (!r.accepted) continue;
      b->base.base_unit = r.unit;
      b->base.prediction = p;
      moved = true;
      break;
    }
    if (!moved) return;
  }
}

std::string StepsSummary(const std::vector<BaseStepRecord>& steps) {
  std::ostringstream s;
  for (const BaseStepRecord& r : steps)
    s << "; its linearised step" << (r.fraction < 1 ? " (half of it)" : "")
      << " predicted chi2 " << Rounded(r.chi2_before) << " to " << Rounded(r.chi2_predicted)
      << ", simulated " << Rounded(r.chi2_simulated)
      << (r.accepted ? ": the base moved there" : ": no lower, not taken");
  return s.str();
}

}  // namespace

double StagnationMargin(double noise_sd_before, double noise_sd_after) {
  return std::max(1.0, kNoiseSds * std::hypot(noise_sd_before, noise_sd_after));
}

double BaseStepThreshold(int rank, double max_noise_per_sigma, double significance) {
  return std::max(1.0, max_noise_per_sigma * max_noise_per_sigma *
                           calibrate::ChiSquareQuantile(1 - significance, std::max(1, rank)));
}

BaseFit SettleBase(ForwardModel& model, const std::vector<Observation>& observations,
                   double floor_factor, double significance,
                   const std::function<void(const std::string&)>& progress,
                   bool settle_within_noise) {
  BaseFit b;
  NoisyChi2 previous;
  for (b.budget_scale = 1;; b.budget_scale *= 2) {
    b.base = model.CalibrateBase(b.budget_scale);
    if (!b.base.ok || b.base.settled) break;
    // Within noise already: more budget could only lower χ² further, and "no missing effect"
    // stands; the extension is for a gap an unsettled fit might have made itself, and for the
    // screen's candidate tests, which need the base at its own optimum (a base on a bound gets
    // the bound probe instead, as before).
    const bool extend = settle_within_noise && std::none_of(b.base.base_unit.begin(),
                                                            b.base.base_unit.end(), AtBound);
    if (!extend && WithinNoise(observations, b.base, floor_factor, significance)) {
      b.within_noise = true;
      break;
    }
    // Stagnation (StagnationMargin): twice the budget lowered the best χ² by less than one
    // standard deviation of a fitted parameter, or by less than the two fits' simulation noise
    // allows: the search has settled where it is, even if a noisy objective never meets the
    // optimiser's own tolerance.
    const NoisyChi2 now = Chi2(observations, b.base.prediction, floor_factor);
    b.chi2_rounds.push_back(now.chi2);
    b.chi2_noise_sd_rounds.push_back(now.noise_sd);
    if (std::isfinite(previous.chi2) &&
        previous.chi2 - now.chi2 < StagnationMargin(previous.noise_sd, now.noise_sd)) {
      b.base.settled = b.stagnated = true;
      b.stagnation_margin = StagnationMargin(previous.noise_sd, now.noise_sd);
      break;
    }
    previous = now;
    if (b.budget_scale >= kMaxBaseBudgetScale) break;
    if (progress)
      progress("the base calibration ended on its budget (" + b.base.termination + ", " +
               std::to_string(b.base.max_evaluations) + " evaluations, best chi2 " +
               Rounded(now.chi2) + ", simulation noise sd " + Rounded(now.noise_sd) +
               "): again with twice the budget");
  }
  if (b.base.ok && !b.base.settled && !b.within_noise)
    b.within_noise = WithinNoise(observations, b.base, floor_factor, significance);
  if (b.base.ok && b.stagnated)
    CheckStagnatedOptimum(model, observations, floor_factor, significance, &b);
  std::ostringstream s;
  s << "base calibration " << b.base.termination << " with " << b.base.max_evaluations
    << " evaluations"
    << (b.budget_scale > 1 ? " (" + std::to_string(b.budget_scale) + "x the study's budget)" : "");
  if (!b.base.ok) return b.summary = s.str(), b;
  if (b.stagnated)
    s << ": settled, twice the budget lowered chi2 by less than " << b.stagnation_margin
      << " (" << (b.stagnation_margin > 1 ? "the simulation noise of the two fits' chi2"
                                          : "one standard deviation of a fitted parameter")
      << ")" << StepsSummary(b.steps);
  if (!b.base.settled) {
    s << ": not settled by the calibration's own criterion";
    const size_t r = b.chi2_rounds.size();
    if (r >= 2)  // the last doubling's drop against the stagnation margin: real progress
      s << "; twice the budget still lowered chi2 by "
        << Rounded(b.chi2_rounds[r - 2] - b.chi2_rounds[r - 1]) << " (" << Rounded(b.chi2_rounds[r - 2])
        << " to " << Rounded(b.chi2_rounds[r - 1]) << "), more than its simulation noise allows ("
        << Rounded(StagnationMargin(b.chi2_noise_sd_rounds[r - 2], b.chi2_noise_sd_rounds[r - 1]))
        << ")";
    if (b.within_noise) s << ", but within noise there (more budget could only lower chi2)";
  }
  const std::vector<Observation> at = WithPrediction(observations, b.base.prediction, floor_factor);
  const int n = static_cast<int>(observations.size()),
            p = static_cast<int>(b.base.base_unit.size());
  // Standardised as the residuals are (by each row's σ), with the sensitivities' own standard
  // errors: a singular value within their size is not resolved above the noise
  // (JacobianNoiseFloor), the calibration's own rule for a J estimated from noisy runs.
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, p), J_sigma = Eigen::MatrixXd::Zero(n, p);
  for (int i = 0; i < n && i < static_cast<int>(b.base.jacobian.size()); ++i)
    for (int j = 0; j < p && j < static_cast<int>(b.base.jacobian[i].size()); ++j) {
      J(i, j) = b.base.jacobian[i][j] / at[i].Sigma();
      if (i < static_cast<int>(b.base.jacobian_sigma.size()) &&
          j < static_cast<int>(b.base.jacobian_sigma[i].size()))
        J_sigma(i, j) = b.base.jacobian_sigma[i][j] / at[i].Sigma();
    }
  const std::vector<std::string> names = model.BaseParameterNames();
  for (int j = 0; j < p; ++j) {
    const double u = b.base.base_unit[j];
    if (!AtBound(u)) continue;
    const std::string name = j < static_cast<int>(names.size()) ? names[j]
                                                                : "parameter " + std::to_string(j);
    b.at_bound.push_back(name + " at its " + (u <= 1e-9 ? "lower" : "upper") + " bound");
    b.bounds.push_back({j, u <= 1e-9});
  }
  for (const std::string& a : b.at_bound) s << "; " << a;
  if (p > 0) {
    b.identifiability = calibrate::AnalyseIdentifiability(
        J, model.BaseParameterNames(), model.BaseSiPerUnit(b.base.base_unit),
        calibrate::JacobianNoiseFloor(J_sigma));
    if (!b.identifiability.Identifiable()) {
      s << "; the data do not determine the base parameters:";
      for (const calibrate::UndeterminedDirection& u : b.identifiability.undetermined)
        s << " " << u.description;
    }
  }
  b.summary = s.str();
  return b;
}

}  // namespace demcal::diagnose
