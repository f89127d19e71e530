#include "diagnose/ranking/evidence.h"

#include <algorithm>
#include <cmath>

#include "calibrate/chi_square.h"
#include "diagnose/ranking/discrepancy_floor.h"
#include "diagnose/ranking/f_distribution.h"

namespace demcal::diagnose {

using calibrate::ChiSquareSurvival;

Evidence EvidenceOf(double chi2_base, double chi2_effect, int k, int n, double significance) {
  Evidence e;
  e.delta_chi2 = chi2_base - chi2_effect;
  e.lr_p_value = ChiSquareSurvival(std::max(0.0, e.delta_chi2), k);
  e.delta_bic = chi2_effect - chi2_base + k * std::log(static_cast<double>(std::max(n, 1)));
  e.significant = e.lr_p_value < significance && e.delta_bic < 0;
  return e;
}

Evidence EvidenceWithFloor(const Eigen::VectorXd& r_base, const Eigen::VectorXd& r_effect,
                           const Eigen::VectorXd& q, int k, int fitted, double significance) {
  const int n = static_cast<int>(r_base.size());
  const int dof = std::max(1, n - fitted - k);
  Evidence e;
  e.floor = EstimateFloor(r_effect, q, dof);
  e.delta_chi2 = FlooredChi2(r_base, q, e.floor) - FlooredChi2(r_effect, q, e.floor);
  e.lr_p_value = e.floor > 0 ? FSurvival(std::max(0.0, e.delta_chi2) / k, k, dof)
                             : ChiSquareSurvival(std::max(0.0, e.delta_chi2), k);
  e.delta_bic = -e.delta_chi2 + k * std::log(static_cast<double>(std::max(n, 1)));
  e.significant = e.lr_p_value < significance && e.delta_bic < 0;
  return e;
}

}  // namespace demcal::diagnose
