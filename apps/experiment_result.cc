// Shared pieces of the experiment runners' result files.
#include <fstream>

#include "apps/experiment_runner.h"
#include "core/version.h"

namespace demcal::apps {

nlohmann::ordered_json FidelityJson(const objectives::Fidelity& f) {
  return {{"name", f.name},
          {"size_scale", f.size_scale},
          {"stiffness_scale", f.stiffness_scale},
          {"rayleigh_fraction", f.rayleigh_fraction}};
}

nlohmann::ordered_json ResultHeader(const ExperimentFile& file, const ExperimentContext& context) {
  nlohmann::ordered_json j;
  j["format"] = "demcal-result/1";
  j["experiment"] = file.experiment;
  j["demcal_version"] = kVersion;
  j["params_file"] = file.source;
  j["description"] = file.description;
  j["fidelity"] = FidelityJson(context.fidelity);
  j["seed"] = file.seed;
  j["replicates"] = context.replicates;
  return j;
}

bool WriteJsonFile(const std::string& path, const nlohmann::ordered_json& value,
                   std::string* error) {
  std::ofstream out(path, std::ios::trunc);
  out << value.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
  out.flush();
  if (!out) {
    if (error) *error = "cannot write '" + path + "'";
    return false;
  }
  return true;
}

}  // namespace demcal::apps
