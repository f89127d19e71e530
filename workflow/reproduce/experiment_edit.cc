#include "workflow/reproduce/experiment_edit.h"

#include "files/json_document.h"

namespace demcal::workflow {
namespace {

nlohmann::ordered_json* FindPair(nlohmann::ordered_json* pairs, const std::string& a,
                                 const std::string& b) {
  for (auto& p : *pairs) {
    const auto& m = p["materials"];
    if (m.size() == 2 && ((m[0] == a && m[1] == b) || (m[0] == b && m[1] == a))) return &p;
  }
  return nullptr;
}

}  // namespace

bool ReadExperimentJson(const std::string& path, nlohmann::ordered_json* out, std::string* error) {
  nlohmann::json checked;  // the one reading discipline (size, depth, duplicate keys)
  if (!ReadJsonFile(path, "experiment file", &checked, error)) return false;
  *out = nlohmann::ordered_json::parse(checked.dump());
  return true;
}

bool ParseEditedExperiment(const nlohmann::ordered_json& experiment, const std::string& source,
                           ExperimentFile* out, std::string* error) {
  // Through its text, so numbers take the types a reader of the written copy sees (an edited
  // integer is signed in memory, unsigned once read back) and the run is the copy's run.
  return ParseExperimentJson(nlohmann::json::parse(experiment.dump()), source, out, error);
}

void SetPairProperty(nlohmann::ordered_json* experiment, const std::string& a, const std::string& b,
                     const std::string& key, double value) {
  nlohmann::ordered_json& interactions = (*experiment)["interactions"];
  if (!interactions.contains("pairs")) interactions["pairs"] = nlohmann::ordered_json::array();
  nlohmann::ordered_json* pair = FindPair(&interactions["pairs"], a, b);
  if (!pair) {
    interactions["pairs"].push_back({{"materials", {a, b}}});
    pair = &interactions["pairs"].back();
    // A listed pair replaces the default for every property: copy the default's.
    if (interactions.contains("default"))
      for (auto& [k, v] : interactions["default"].items()) (*pair)[k] = v;
  }
  (*pair)[key] = value;
}

void SetSpeciesClump(nlohmann::ordered_json* experiment, const std::string& name,
                     const std::vector<double>& semi_axes, int count) {
  if (!experiment->contains("species")) return;
  for (nlohmann::ordered_json& s : (*experiment)["species"]) {
    if (s.value("name", "") != name) continue;
    if (count <= 1) s.erase("clump");
    else s["clump"] = {{"ellipsoid", {{"semi_axes", semi_axes}, {"sphere_count", count}}}};
  }
}

bool SetFunnelOrificeRule(nlohmann::ordered_json* experiment, double effective_orifice_diameter_m,
                          double beverloo_k) {
  nlohmann::ordered_json& funnel = (*experiment)["segregation"]["funnel"];
  if (funnel.is_boolean() && !funnel.get<bool>()) return false;
  if (!funnel.is_object()) funnel = nlohmann::ordered_json::object();  // true: the defaults
  funnel.erase("orifice_diameter_m");  // the file format refuses a fixed orifice beside the rule
  funnel["effective_orifice_diameter_m"] = effective_orifice_diameter_m;
  funnel["beverloo_k"] = beverloo_k;
  return true;
}

double PairProperty(const nlohmann::ordered_json& experiment, const std::string& a,
                    const std::string& b, const std::string& key, double fallback) {
  if (!experiment.contains("interactions")) return fallback;
  nlohmann::ordered_json interactions = experiment["interactions"];
  if (interactions.contains("pairs"))
    if (const auto* p = FindPair(&interactions["pairs"], a, b); p && p->contains(key))
      return (*p)[key].get<double>();
  if (interactions.contains("default") && interactions["default"].contains(key))
    return interactions["default"][key].get<double>();
  return fallback;
}

}  // namespace demcal::workflow
