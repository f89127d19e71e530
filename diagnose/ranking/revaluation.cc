#include "diagnose/ranking/revaluation.h"

#include <cmath>
#include <sstream>

namespace demcal::diagnose {

bool IsRevaluation(const EffectParameter& p, double value) {
  return p.assumed > 0 && std::isfinite(value) && std::abs(value) <= p.assumed;
}

int RevaluationOfTie(const EffectParameter& first, double first_value,
                     const EffectParameter& second, double second_value) {
  const bool a = IsRevaluation(first, first_value), b = IsRevaluation(second, second_value);
  if (a && b) return 0;
  if (a && first_value < 0) return 0;
  if (b && second_value < 0) return 1;
  return -1;
}

std::string RevaluationText(const std::string& key, const EffectParameter& p, double value,
                            double chi2_per_dof) {
  std::ostringstream s;
  s.precision(3);
  const std::string unit = p.unit.empty() ? "" : " " + p.unit;
  s << key << ", " << EffectDirection(p, value) << ": " << p.name << " = " << value << unit
    << " against the assumed " << p.assumed << unit << " (chi2/dof " << chi2_per_dof << " with it)";
  return s.str();
}

}  // namespace demcal::diagnose
