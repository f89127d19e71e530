#include "calibrate/target_gain.h"

#include <cmath>
#include <sstream>

#include "calibrate/identifiability.h"
#include "calibrate/parameter_covariance.h"

namespace demcal::calibrate {

std::vector<TargetGain> RankCandidateTargets(const Eigen::MatrixXd& jacobian,
                                             const std::vector<CandidateTarget>& candidates,
                                             const std::vector<std::string>& names,
                                             const std::vector<double>& si_per_unit) {
  const Eigen::Index n = jacobian.cols();
  const ParameterCovariance before = CovarianceFromJacobian(jacobian, si_per_unit);
  const int undetermined_before =
      static_cast<int>(AnalyseIdentifiability(jacobian, names, si_per_unit).undetermined.size());
  std::vector<TargetGain> gains;
  for (const CandidateTarget& c : candidates) {
    TargetGain g;
    g.name = c.name;
    g.sigma_before = before.sigma;
    g.undetermined_before = undetermined_before;
    if (static_cast<Eigen::Index>(c.sensitivity.size()) != n) {
      g.description = c.name + ": " + std::to_string(c.sensitivity.size()) +
                      " sensitivities given for " + std::to_string(n) + " parameters; ignored";
      gains.push_back(std::move(g));
      continue;
    }
    Eigen::MatrixXd augmented(jacobian.rows() + 1, n);
    augmented.topRows(jacobian.rows()) = jacobian;
    for (Eigen::Index k = 0; k < n; ++k) augmented(jacobian.rows(), k) = c.sensitivity[k];
    const ParameterCovariance after = CovarianceFromJacobian(augmented, si_per_unit);
    g.sigma_after = after.sigma;
    g.identifiable_after = after.identifiable;
    g.undetermined_after =
        static_cast<int>(AnalyseIdentifiability(augmented, names, si_per_unit).undetermined.size());
    g.lifts_valley = g.undetermined_after < g.undetermined_before;
    std::ostringstream d;
    d.precision(3);
    d << "adding " << c.name << (g.lifts_valley ? " lifts the valley" : "") << ":";
    for (Eigen::Index k = 0; k < n; ++k) {
      const double b = g.sigma_before[k], a = g.sigma_after[k];
      g.shrink.push_back(!std::isfinite(b) ? (std::isfinite(a) ? 0.0 : 1.0)
                                           : (b > 0 ? a / b : 1.0));
      d << (k ? "," : "") << " sigma " << names[k] << " " << b << " -> " << a;
      if (std::isfinite(b) && std::isfinite(a)) d << " (x" << g.shrink.back() << ")";
    }
    g.description = d.str();
    gains.push_back(std::move(g));
  }
  return gains;
}

}  // namespace demcal::calibrate
