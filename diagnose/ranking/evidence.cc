#include "diagnose/ranking/evidence.h"

#include <algorithm>
#include <cmath>

#include "calibrate/chi_square.h"

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

}  // namespace demcal::diagnose
