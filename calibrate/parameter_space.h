#pragma once
// ParameterSpace: the DEM inputs a calibration varies — each a named, bounded value written into
// one slot of the particle model (a pair property of the interaction table, both orders of the
// pair). Optimisers work in the unit cube [0, 1]^n; a parameter on a log scale is uniform in
// log(value) there, which suits interfacial energies spanning decades.
//
//   ParameterSpace space;
//   space.parameters.push_back({"mu_r_BP", PairProperty::kRollingFriction, 0, 0, 0.02, 0.8, 0.1});
//   std::string error;
//   if (!space.IsValid(model, &error)) ...;
//   space.Apply({0.35}, &model);   // BP–BP rolling friction := 0.35
//
// Thread-safety: immutable after set-up; Apply writes only into the model it is given.
#include <string>
#include <vector>

#include "calibrate/condition.h"
#include "calibrate/pair_property.h"
#include "calibrate/parameter_curve.h"
#include "core/scene/scene.h"

namespace demcal::calibrate {

struct Parameter {
  std::string name;       // unique, used in tables and journals
  PairProperty property = PairProperty::kSlidingFriction;
  int material_i = 0;     // the pair (indices into the model's materials); symmetric
  int material_j = 0;
  double lower = 0;       // bounds in SI units, lower < upper
  double upper = 1;
  double start = 0.5;     // first candidate, inside the bounds
  bool log_scale = false; // uniform in log(value) in the unit cube (needs lower > 0)
  // Applies only to targets whose condition includes this one (Γ of EP at 0.5 wt%); empty:
  // every target.
  Condition when;
  // >= 0: a coefficient of curves[curve], written into the model only through that curve.
  int curve = -1;
};

struct ParameterSpace {
  std::vector<Parameter> parameters;
  std::vector<ParameterCurve> curves;
  // Each list: parameter indices whose values must not decrease in this order (Γ non-decreasing
  // in the coating level). A candidate that breaks one is infeasible: it is never simulated.
  std::vector<std::vector<int>> non_decreasing;

  size_t Size() const { return parameters.size(); }
  // Names the first bad field ("parameters[1].min") and the allowed range; `paths`, when given,
  // names each parameter as its file does ("parameters[0].curve.coefficients[1]").
  bool IsValid(const core::Scene& model, std::string* error,
               const std::vector<std::string>& paths = {}) const;
  // Writes values (SI, one per parameter) into the model's pair table: every parameter without
  // a `when`, and every curve (which needs a condition: use the overload below).
  void Apply(const std::vector<double>& values, core::Scene* model) const;
  // The model of one target: the parameters whose `when` the condition includes, and every
  // curve at the condition's covariate. False (with why) when a curve gives no valid value.
  bool Apply(const std::vector<double>& values, const Condition& condition, core::Scene* model,
             std::string* why) const;
  // The declared constraints hold; false with the first broken one in *why.
  bool Feasible(const std::vector<double>& values, std::string* why) const;
  std::vector<double> ToUnit(const std::vector<double>& values) const;
  std::vector<double> FromUnit(const std::vector<double>& unit) const;
  std::vector<double> Start() const;
  // "mu_r_BP=0.35, gamma_EP=0.046 J/m2"
  std::string Describe(const std::vector<double>& values) const;
};

}  // namespace demcal::calibrate
