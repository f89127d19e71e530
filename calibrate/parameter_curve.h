#pragma once
// ParameterCurve: a pair property that follows a covariate of the condition instead of being
// one number — Γ of EP against the coating level w (the paper's Fig. 6) — fitted jointly to the
// targets of every condition. Its coefficients are ordinary parameters of the ParameterSpace
// (bounded, in the optimiser's vector); the curve maps them to the property at a target's
// covariate:
//   linear                 p(w) = c0 + c1·w
//   linear_through_origin  p(w) = c0·w
//   power_law              p(w) = c0·w^c1  (w > 0)
//
//   ParameterCurve c{.name = "gamma_EP(w)", .property = PairProperty::kInterfacialEnergy,
//                    .covariate = "coating_PEG_wt_pct", .form = CurveForm::kLinear,
//                    .coefficients = {1, 2}};
//   double gamma;  std::string why;
//   if (!c.Evaluate(values, {{"coating_PEG_wt_pct", "2.5"}}, &gamma, &why)) ...;
#include <string>
#include <vector>

#include "calibrate/condition.h"
#include "calibrate/pair_property.h"

namespace demcal::calibrate {

enum class CurveForm { kLinear, kLinearThroughOrigin, kPowerLaw };

const char* CurveFormKey(CurveForm form);  // "linear", ...
bool CurveFormFromKey(const std::string& key, CurveForm* out);
int CurveCoefficientCount(CurveForm form);
std::vector<std::string> CurveFormKeys();

struct ParameterCurve {
  std::string name;
  PairProperty property = PairProperty::kInterfacialEnergy;
  int material_i = 0, material_j = 0;  // the pair (symmetric)
  std::string covariate;               // a condition column with numbers
  CurveForm form = CurveForm::kLinear;
  std::vector<int> coefficients;       // indices into the space's parameter vector
  // The condition gives the covariate a number the form accepts (w > 0 for a power law); false
  // with why otherwise: then no candidate can be evaluated under this condition.
  bool Covers(const Condition& condition, double* w, std::string* why) const;
  // The property at the condition's covariate; false (with why) when Covers fails or the value
  // is not a finite number >= 0.
  bool Evaluate(const std::vector<double>& values, const Condition& condition, double* out,
                std::string* why) const;
};

}  // namespace demcal::calibrate
