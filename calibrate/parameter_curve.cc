#include "calibrate/parameter_curve.h"

#include <cmath>
#include <sstream>

namespace demcal::calibrate {
namespace {

struct FormInfo {
  CurveForm form;
  const char* key;
  int coefficients;
};

constexpr FormInfo kForms[] = {{CurveForm::kLinear, "linear", 2},
                               {CurveForm::kLinearThroughOrigin, "linear_through_origin", 1},
                               {CurveForm::kPowerLaw, "power_law", 2}};

const FormInfo& Info(CurveForm form) {
  for (const FormInfo& f : kForms)
    if (f.form == form) return f;
  return kForms[0];
}

}  // namespace

const char* CurveFormKey(CurveForm form) { return Info(form).key; }
int CurveCoefficientCount(CurveForm form) { return Info(form).coefficients; }

bool CurveFormFromKey(const std::string& key, CurveForm* out) {
  for (const FormInfo& f : kForms)
    if (key == f.key) return *out = f.form, true;
  return false;
}

std::vector<std::string> CurveFormKeys() {
  std::vector<std::string> keys;
  for (const FormInfo& f : kForms) keys.push_back(f.key);
  return keys;
}

bool ParameterCurve::Covers(const Condition& condition, double* w, std::string* why) const {
  if (!ConditionNumber(condition, covariate, w)) {
    const auto cell = condition.find(covariate);
    *why = name + ": the condition (" + DescribeCondition(condition) + ") " +
           (cell == condition.end() ? "has no '" + covariate + "'"
                                    : "gives '" + covariate + "' a word, '" + cell->second +
                                          "', not a number");
    return false;
  }
  if (form == CurveForm::kPowerLaw && !(*w > 0)) {
    *why = name + ": a power law needs " + covariate + " > 0 (the condition gives " +
           condition.at(covariate) + ")";
    return false;
  }
  return true;
}

bool ParameterCurve::Evaluate(const std::vector<double>& values, const Condition& condition,
                              double* out, std::string* why) const {
  double w = 0;
  if (!Covers(condition, &w, why)) return false;
  const double c0 = values[coefficients[0]];
  switch (form) {
    case CurveForm::kLinear: *out = c0 + values[coefficients[1]] * w; break;
    case CurveForm::kLinearThroughOrigin: *out = c0 * w; break;
    case CurveForm::kPowerLaw: *out = c0 * std::pow(w, values[coefficients[1]]); break;
  }
  if (!(std::isfinite(*out) && *out >= 0)) {
    std::ostringstream text;
    text << name << " = " << *out << " at " << covariate << " = " << w
         << ": a pair property must be >= 0";
    *why = text.str();
    return false;
  }
  return true;
}

}  // namespace demcal::calibrate
