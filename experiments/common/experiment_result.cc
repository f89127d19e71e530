// Shared pieces of the experiment runners' results: the typed result and the header of the
// result files.
#include "experiments/common/experiment_result.h"

#include "core/version.h"
#include "experiments/common/experiment_runner.h"
#include "outputs/exit_codes.h"

namespace demcal::workflow {

int ExitCodeOf(ExperimentStatus status) {
  switch (status) {
    case ExperimentStatus::kOk: return kExitOk;
    case ExperimentStatus::kRunFailed: return kExitRunFailed;
    case ExperimentStatus::kInvalidInput: return kExitInvalidInput;
    case ExperimentStatus::kOutputUnavailable: return kExitInvalidInput;
    case ExperimentStatus::kOutputError: return kExitOutputError;
  }
  return kExitInternalError;
}

const objectives::Summary* ExperimentResult::Value(const std::string& name) const {
  for (const NamedEstimate& v : values)
    if (v.name == name) return &v.value;
  return nullptr;
}

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
