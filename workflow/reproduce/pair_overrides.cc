#include "workflow/reproduce/pair_overrides.h"

#include <algorithm>
#include <utility>

#include "core/math/number_text.h"
#include "workflow/reproduce/experiment_edit.h"

namespace demcal::workflow {

bool ApplyPairOverrides(const WorkflowFile& w, nlohmann::ordered_json* experiment,
                        std::string* error) {
  std::vector<std::string> materials;
  const nlohmann::ordered_json& file = *experiment;
  if (file.contains("materials") && file["materials"].is_array())
    for (const auto& m : file["materials"])
      if (m.is_object()) materials.push_back(m.value("name", ""));
  nlohmann::ordered_json edited = *experiment;  // the file is changed only when all are valid
  std::string said;
  for (size_t i = 0; i < w.segregation.pair_overrides.size(); ++i) {
    const PairOverride& o = w.segregation.pair_overrides[i];
    const std::string field = w.source + ": segregation.pair_overrides[" + std::to_string(i) + "]";
    for (const std::string& m : {o.material_a, o.material_b})
      if (std::find(materials.begin(), materials.end(), m) == materials.end()) {
        std::string names;
        for (const std::string& n : materials) names += (names.empty() ? "" : ", ") + n;
        return *error = field + ".materials: '" + m + "' is not a material of '" +
                        w.segregation.experiment_file + "' (one of " + names + ")",
               false;
      }
    for (const WorkflowSpecies& s : w.species)
      if (o.material_a == s.name && o.material_b == s.name && o.property == s.property)
        return *error = field + ": the " + s.property + " of " + s.name + "-" + s.name +
                        " is what stage 1 calibrates (or holds) for species '" + s.name +
                        "'; override only pairs that no stage sets",
               false;
    SetPairProperty(&edited, o.material_a, o.material_b, o.property, o.value);
    said += " " + o.property + " " + o.material_a + "-" + o.material_b + " set to " +
            core::NumberText(o.value) + " by the workflow (" + o.note + ").";
  }
  if (!said.empty()) edited["description"] = edited.value("description", std::string()) + said;
  *experiment = std::move(edited);
  return true;
}

}  // namespace demcal::workflow
