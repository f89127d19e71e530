// Shared pieces of the experiment runners' result files.
#include "experiments/common/experiment_runner.h"
#include "core/version.h"

namespace demcal::workflow {

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

}  // namespace demcal::workflow
