#include "experiments/common/experiment_sections.h"

#include "core/limits/physical_limits.h"
#include "files/scene_json_sections.h"

#include <cmath>
#include <cstring>
#include <utility>

namespace demcal::workflow {

using nlohmann::json;

void ParseFeed(const json& value, const std::string& path, const core::Scene& model,
               objectives::Feed* feed, JsonStatus* status) {
  JsonFields f(value, path,
               {"components", "mass_kg", "mass_rate_kg_s", "start_s", "velocity_m_s"}, status);
  const json* components = f.Array("components", kRequired);
  f.Number("mass_kg", &feed->mass_kg, kRequired, Range::LeftOpen(0, 1e4, "kg"));
  f.Number("mass_rate_kg_s", &feed->mass_rate_kg_s, kRequired,
           Range::Of(core::limits::kMassRate, "kg/s"));
  f.Number("start_s", &feed->start_s, kOptional, Range::Closed(0, 1e4, "s"));
  f.Vector("velocity_m_s", &feed->velocity_m_s, kOptional);
  const core::Vec3& v = feed->velocity_m_s;
  if (const double speed = std::hypot(v.x, v.y, v.z);  // no overflow of the squares
      f.ok() && !core::limits::kSpeed.Contains(speed))
    f.Fail("velocity_m_s", "has magnitude " + FormatNumber(speed) +
                               " m/s, outside the allowed range " + core::limits::kSpeed.Text() +
                               " m/s");
  if (!components || !status->ok()) return;
  const std::vector<std::string> names = internal::SpeciesNames(model);
  feed->components.clear();
  for (size_t k = 0; k < components->size(); ++k) {
    JsonFields c((*components)[k], IndexPath(f.PathOf("components"), k),
                 {"species", "mass_fraction"}, status);
    objectives::FeedComponent component;
    component.species = internal::ReadNameReference(c, "species", "species", names, status);
    c.Number("mass_fraction", &component.mass_fraction, kRequired, Range::LeftOpen(0, 1));
    feed->components.push_back(component);
  }
  std::string error;
  if (status->ok() && !feed->IsValid(model, path, &error)) status->Fail(error);
}

void ParseSettle(const json& value, const std::string& path, objectives::SettleCriteria* settle,
                 JsonStatus* status) {
  JsonFields f(value, path,
               {"specific_kinetic_J_kg", "min_settle_s", "check_interval_s", "max_time_s",
                "surface_window_s", "surface_change_d"},
               status);
  f.Number("specific_kinetic_J_kg", &settle->specific_kinetic_J_kg, kOptional,
           Range::LeftOpen(0, 1e3, "J/kg"));
  f.Number("min_settle_s", &settle->min_settle_s, kOptional, Range::Closed(0, 1e3, "s"));
  f.Number("check_interval_s", &settle->check_interval_s, kOptional,
           Range::LeftOpen(0, 10, "s"));
  f.Number("max_time_s", &settle->max_time_s, kOptional, Range::LeftOpen(0, 1e4, "s"));
  f.Number("surface_window_s", &settle->surface_window_s, kOptional, Range::Closed(0, 1e3, "s"));
  f.Number("surface_change_d", &settle->surface_change_d, kOptional, Range::LeftOpen(0, 10));
}

namespace internal {
std::string UserFacing(const std::string& problem) {
  static const std::pair<const char*, const char*> kPaths[] = {
      {"ReposeAngleOptions: ", "field 'aor.angle': "},
      {"DischargeOptions: ", "field 'discharge.analysis': "},
      {"CoV: ", "field 'segregation.bins': "},
  };
  for (const auto& [prefix, path] : kPaths)
    if (problem.rfind(prefix, 0) == 0) return path + problem.substr(std::strlen(prefix));
  return problem;
}
}  // namespace internal

int ReadMaterial(JsonFields& fields, const std::string& key, const core::Scene& model,
                 JsonStatus* status) {
  return internal::ReadNameReference(fields, key, "material", internal::MaterialNames(model),
                                     status);
}

}  // namespace demcal::workflow
