#include "calibrate/parameter_space.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace demcal::calibrate {
namespace {

struct PropertyInfo {
  PairProperty property;
  const char* key;
  const char* unit;
  double max;  // physical upper limit of the property
};

constexpr PropertyInfo kProperties[] = {
    {PairProperty::kSlidingFriction, "sliding_friction", "", 10},
    {PairProperty::kRollingFriction, "rolling_friction", "", 10},
    {PairProperty::kRestitution, "restitution", "", 1},
    {PairProperty::kInterfacialEnergy, "interfacial_energy_J_m2", "J/m2", 1e3},
};

const PropertyInfo& Info(PairProperty property) {
  for (const PropertyInfo& p : kProperties)
    if (p.property == property) return p;
  return kProperties[0];
}

double& Slot(core::PairParameters& pair, PairProperty property) {
  switch (property) {
    case PairProperty::kRollingFriction: return pair.rolling_friction;
    case PairProperty::kRestitution: return pair.restitution;
    case PairProperty::kInterfacialEnergy: return pair.interfacial_energy_J_m2;
    case PairProperty::kSlidingFriction: break;
  }
  return pair.sliding_friction;
}

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

const char* PairPropertyKey(PairProperty property) { return Info(property).key; }
const char* PairPropertyUnit(PairProperty property) { return Info(property).unit; }

bool PairPropertyFromKey(const std::string& key, PairProperty* out) {
  for (const PropertyInfo& p : kProperties)
    if (key == p.key) return *out = p.property, true;
  return false;
}

bool ParameterSpace::IsValid(const core::Scene& model, std::string* error) const {
  if (parameters.empty()) return Fail(error, "parameters: at least one parameter is needed");
  std::set<std::string> names;
  std::set<std::tuple<int, int, int>> slots;
  const int materials = static_cast<int>(model.materials.size());
  for (size_t k = 0; k < parameters.size(); ++k) {
    const Parameter& p = parameters[k];
    const std::string at = "parameters[" + std::to_string(k) + "]";
    const double max = Info(p.property).max;
    if (p.name.empty()) return Fail(error, at + ".name: must not be empty");
    if (!names.insert(p.name).second) return Fail(error, at + ".name: '" + p.name + "' is used twice");
    if (p.material_i < 0 || p.material_i >= materials || p.material_j < 0 || p.material_j >= materials)
      return Fail(error, at + ".materials: not a material of the model");
    const auto slot = std::make_tuple(static_cast<int>(p.property), std::min(p.material_i, p.material_j),
                                      std::max(p.material_i, p.material_j));
    if (!slots.insert(slot).second) return Fail(error, at + ": sets the same pair property as an earlier parameter");
    if (!(p.lower >= 0 && p.lower < p.upper && p.upper <= max))
      return Fail(error, at + ".lower/upper: need 0 <= lower < upper <= " + std::to_string(max) +
                             " (got " + std::to_string(p.lower) + ", " + std::to_string(p.upper) + ")");
    if (p.property == PairProperty::kRestitution && p.lower <= 0)
      return Fail(error, at + ".lower: a restitution must be > 0");
    if (p.log_scale && p.lower <= 0) return Fail(error, at + ".log_scale: needs lower > 0");
    if (!(p.start >= p.lower && p.start <= p.upper))
      return Fail(error, at + ".start: must lie in [lower, upper] = [" + std::to_string(p.lower) +
                             ", " + std::to_string(p.upper) + "]");
  }
  return true;
}

void ParameterSpace::Apply(const std::vector<double>& values, core::Scene* model) const {
  const size_t n = model->materials.size();
  for (size_t k = 0; k < parameters.size(); ++k) {
    const Parameter& p = parameters[k];
    Slot(model->pair_parameters[p.material_i * n + p.material_j], p.property) = values[k];
    Slot(model->pair_parameters[p.material_j * n + p.material_i], p.property) = values[k];
  }
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
