#include "calibrate/parameter_space.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "objectives/common/input_limits.h"

namespace demcal::calibrate {
namespace {

namespace limits = objectives::limits;  // Limit::Text: the range format of every message

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

bool ParameterSpace::IsValid(const core::Scene& model, std::string* error,
                             const std::vector<std::string>& paths) const {
  if (parameters.empty()) return Fail(error, "parameters: at least one parameter is needed");
  std::set<std::string> names;
  std::set<std::tuple<int, int, int, std::string>> slots;
  const int materials = static_cast<int>(model.materials.size());
  for (size_t k = 0; k < parameters.size(); ++k) {
    const Parameter& p = parameters[k];
    const std::string at = k < paths.size() ? paths[k] : "parameters[" + std::to_string(k) + "]";
    const double min = PairPropertyMin(p.property), max = PairPropertyMax(p.property);
    if (p.name.empty()) return Fail(error, at + ".name: must not be empty");
    if (!names.insert(p.name).second) return Fail(error, at + ".name: '" + p.name + "' is used twice");
    if (p.material_i < 0 || p.material_i >= materials || p.material_j < 0 || p.material_j >= materials)
      return Fail(error, at + ".materials: not a material of the model");
    const auto slot = std::make_tuple(static_cast<int>(p.property), std::min(p.material_i, p.material_j),
                                      std::max(p.material_i, p.material_j), DescribeCondition(p.when));
    if (p.curve < 0 && !slots.insert(slot).second)
      return Fail(error, at + ": sets the same pair property under the same condition as an earlier parameter");
    if (p.curve >= 0) {  // a curve coefficient: any finite bounds (an intercept, an exponent)
      if (!(std::isfinite(p.lower) && std::isfinite(p.upper) && p.lower < p.upper))
        return Fail(error, at + ".min/max: need finite min < max");
    } else if (!(p.lower >= min && p.lower < p.upper && p.upper <= max))
      return Fail(error, at + ".min/max: need min < max within " + limits::Closed(min, max).Text() +
                             " (got " + limits::Closed(p.lower, p.upper).Text() + ")");
    // A species' own property: the pair of its material with itself names it.
    if (p.property == PairProperty::kAspectRatio && p.material_i != p.material_j)
      return Fail(error, at + ".materials: an aspect_ratio names one material twice ([\"EP\", "
                             "\"EP\"]): it is the shape of that material's species");
    if (p.property == PairProperty::kRestitution && p.lower <= 0)
      return Fail(error, at + ".min: a restitution must be > 0");
    if (p.log_scale && p.lower <= 0) return Fail(error, at + ".log_scale: needs min > 0");
    if (!(p.start >= p.lower && p.start <= p.upper))
      return Fail(error, at + ".start: must lie in [min, max] = " +
                             limits::Closed(p.lower, p.upper).Text());
  }
  for (size_t c = 0; c < curves.size(); ++c)
    for (int k : curves[c].coefficients)
      if (k < 0 || k >= static_cast<int>(parameters.size()) || parameters[k].curve != static_cast<int>(c))
        return Fail(error, "curves[" + std::to_string(c) + "]: coefficient index out of place");
  for (const std::vector<int>& chain : non_decreasing)
    for (int k : chain)
      if (k < 0 || k >= static_cast<int>(parameters.size()))
        return Fail(error, "non_decreasing: names a parameter that does not exist");
  return true;
}

void ParameterSpace::Apply(const std::vector<double>& values, core::Scene* model) const {
  std::string ignored;
  Apply(values, Condition{}, model, &ignored);
}

bool ParameterSpace::Apply(const std::vector<double>& values, const Condition& condition,
                           core::Scene* model, std::string* why) const {
  for (size_t k = 0; k < parameters.size(); ++k) {
    const Parameter& p = parameters[k];
    if (p.curve < 0 && ConditionIncludes(condition, p.when))
      SetPairProperty(p.property, p.material_i, p.material_j, values[k], model);
  }
  bool ok = true;
  for (const ParameterCurve& c : curves) {
    double value = 0;
    if (c.Evaluate(values, condition, &value, why))
      SetPairProperty(c.property, c.material_i, c.material_j, value, model);
    else
      ok = false;
  }
  return ok;
}

bool ParameterSpace::Feasible(const std::vector<double>& values, std::string* why) const {
  for (const std::vector<int>& chain : non_decreasing)
    for (size_t k = 1; k < chain.size(); ++k)
      if (values[chain[k]] < values[chain[k - 1]]) {
        *why = "non_decreasing: " + parameters[chain[k]].name + " < " + parameters[chain[k - 1]].name;
        return false;
      }
  return true;
}

std::vector<double> ParameterSpace::ToUnit(const std::vector<double>& values) const {
  std::vector<double> unit(values.size());
  for (size_t k = 0; k < parameters.size(); ++k) {
    const Parameter& p = parameters[k];
    unit[k] = p.log_scale ? std::log(values[k] / p.lower) / std::log(p.upper / p.lower)
                          : (values[k] - p.lower) / (p.upper - p.lower);
  }
  return unit;
}

std::vector<double> ParameterSpace::FromUnit(const std::vector<double>& unit) const {
  std::vector<double> values(unit.size());
  for (size_t k = 0; k < parameters.size(); ++k) {
    const Parameter& p = parameters[k];
    const double u = std::clamp(unit[k], 0.0, 1.0);
    values[k] = p.log_scale ? p.lower * std::pow(p.upper / p.lower, u) : p.lower + u * (p.upper - p.lower);
  }
  return values;
}

std::vector<double> ParameterSpace::Start() const {
  std::vector<double> start;
  for (const Parameter& p : parameters) start.push_back(p.start);
  return start;
}

std::string ParameterSpace::Describe(const std::vector<double>& values) const {
  std::ostringstream out;
  out.precision(4);
  for (size_t k = 0; k < parameters.size(); ++k) {
    const char* unit = PairPropertyUnit(parameters[k].property);
    out << (k ? ", " : "") << parameters[k].name << "=" << values[k] << (*unit ? " " : "") << unit;
  }
  return out.str();
}

}  // namespace demcal::calibrate
