#include "diagnose/loop/base_fit.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>

#include "diagnose/gap/gap_significance.h"
#include "diagnose/loop/fit_state.h"

namespace demcal::diagnose {

bool SettledTermination(const std::string& termination) {
  return termination == "within_noise" || termination == "converged" ||
         termination == "out_of_range";
}

namespace {

double Chi2(const std::vector<Observation>& observations, const Prediction& p,
            double floor_factor) {
  double chi2 = 0;
  for (const Observation& o : WithPrediction(observations, p, floor_factor))
    chi2 += o.Residual() * o.Residual();
  return chi2;
}

}  // namespace

BaseFit SettleBase(ForwardModel& model, const std::vector<Observation>& observations,
                   double floor_factor, double significance,
                   const std::function<void(const std::string&)>& progress) {
  BaseFit b;
  double previous = INFINITY;
  for (b.budget_scale = 1;; b.budget_scale *= 2) {
    b.base = model.CalibrateBase(b.budget_scale);
    if (!b.base.ok || b.base.settled) break;
    // Within noise already: more budget could only lower χ² further, and "no missing effect"
    // stands; the extension is for a gap an unsettled fit might have made itself.
    const std::vector<Observation> here =
        WithPrediction(observations, b.base.prediction, floor_factor);
    if (b.base.prediction.ok &&
        !TestGap(here, static_cast<int>(b.base.base_unit.size()), {significance}).gap_detected) {
      b.within_noise = true;
      break;
    }
    // Stagnation: twice the budget lowered the best χ² by less than 1 (one standard deviation
    // of a fitted parameter, the profile-likelihood unit): the search has settled where it is,
    // even if a noisy objective never meets the optimiser's own tolerance.
    const double chi2 =
        b.base.prediction.ok ? Chi2(observations, b.base.prediction, floor_factor) : INFINITY;
    if (chi2 > previous - 1) {
      b.base.settled = b.stagnated = true;
      break;
    }
    previous = chi2;
    if (b.budget_scale >= kMaxBaseBudgetScale) break;
    if (progress)
      progress("the base calibration ended on its budget (" + b.base.termination + ", " +
               std::to_string(b.base.max_evaluations) +
               " evaluations): again with twice the budget");
  }
  std::ostringstream s;
  s << "base calibration " << b.base.termination << " with " << b.base.max_evaluations
    << " evaluations"
    << (b.budget_scale > 1 ? " (" + std::to_string(b.budget_scale) + "x the study's budget)" : "");
  if (!b.base.ok) return b.summary = s.str(), b;
  if (b.stagnated) s << ": settled, twice the budget lowered chi2 by less than 1";
  if (!b.base.settled)
    s << ": not settled by the calibration's own criterion"
      << (b.within_noise ? ", but within noise there (more budget could only lower chi2)" : "");
  const std::vector<Observation> at = WithPrediction(observations, b.base.prediction, floor_factor);
  const int n = static_cast<int>(observations.size()),
            p = static_cast<int>(b.base.base_unit.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, p);
  for (int i = 0; i < n && i < static_cast<int>(b.base.jacobian.size()); ++i)
    for (int j = 0; j < p && j < static_cast<int>(b.base.jacobian[i].size()); ++j)
      J(i, j) = b.base.jacobian[i][j] / at[i].Sigma();
  // On a bound: the unit coordinate at 0 or 1 up to rounding (optimisers clamp to the bound
  // exactly; 1e-9 only absorbs the unit map's arithmetic, it is not a tolerance on the fit).
  const std::vector<std::string> names = model.BaseParameterNames();
  for (int j = 0; j < p; ++j) {
    const double u = b.base.base_unit[j];
    if (u > 1e-9 && u < 1 - 1e-9) continue;
    const std::string name = j < static_cast<int>(names.size()) ? names[j]
                                                                : "parameter " + std::to_string(j);
    b.at_bound.push_back(name + " at its " + (u <= 1e-9 ? "lower" : "upper") + " bound");
  }
  for (const std::string& a : b.at_bound) s << "; " << a;
  if (p > 0) {
    b.identifiability = calibrate::AnalyseIdentifiability(J, model.BaseParameterNames(),
                                                          model.BaseSiPerUnit(b.base.base_unit));
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
