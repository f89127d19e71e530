#pragma once
// Parsers of the parts that several experiment sections share: the feed (what is poured), the
// settling criterion and a material or species reference by name.
#include <nlohmann/json.hpp>
#include <string>

#include "files/json_fields.h"
#include "core/scene/scene.h"
#include "objectives/common/feed.h"
#include "objectives/common/settled_run.h"

namespace demcal::workflow {

// {"components": [{"species": name, "mass_fraction": w}, ...], "mass_kg", "mass_rate_kg_s",
//  "start_s", "velocity_m_s"}
void ParseFeed(const nlohmann::json& value, const std::string& path, const core::Scene& model,
               objectives::Feed* feed, JsonStatus* status);

// {"specific_kinetic_J_kg", "min_settle_s", "check_interval_s", "max_time_s",
//  "surface_window_s", "surface_change_d"}
void ParseSettle(const nlohmann::json& value, const std::string& path,
                 objectives::SettleCriteria* settle, JsonStatus* status);

// The required material name `key` of `fields`, as an index of model.materials.
int ReadMaterial(JsonFields& fields, const std::string& key, const core::Scene& model,
                 JsonStatus* status);

namespace internal {
// An options struct's IsValid message names the struct ("ReposeAngleOptions: ..."); the user
// knows the JSON path ("aor.angle: ..."). Unknown prefixes pass unchanged.
std::string UserFacing(const std::string& problem);
}  // namespace internal

// The end of every section parser: the settings' own cross-field checks (IsValid(model, &problem)),
// then either *out = parsed, or *error = "<source>: <first problem>".
template <class Settings>
bool FinishSection(JsonStatus& status, const std::string& source, const core::Scene& model,
                   const Settings& parsed, Settings* out, std::string* error) {
  std::string problem;
  if (status.ok() && !parsed.IsValid(model, &problem)) status.Fail(internal::UserFacing(problem));
  if (!status.ok()) {
    if (error) *error = source + ": " + status.message();
    return false;
  }
  *out = parsed;
  return true;
}

}  // namespace demcal::workflow
