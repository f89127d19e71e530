#include "workflow/experiments/experiment_registry.h"

#include "calibrate/probes/aor_probe.h"
#include "calibrate/probes/discharge_probe.h"
#include "workflow/files/aor_json.h"
#include "workflow/files/discharge_json.h"

namespace demcal::workflow {
namespace {

// Parses the section into Settings, validates the scene Build makes for the file's seed, and
// wraps the settings in the Probe.
template <class Probe, class Settings, class Parse, class Build>
std::unique_ptr<calibrate::ExperimentProbe> MakeProbe(const ExperimentFile& file, const core::Scene& model,
                                                      Parse parse, Build build, std::string* error) {
  Settings settings;
  if (!parse(file.section, file.source, model, &settings, error)) return nullptr;
  std::string why;
  if (!build(model, settings, file.seed).IsValid(&why)) {
    *error = file.source + ": the " + file.experiment + " scene is invalid: " + why;
    return nullptr;
  }
  return std::make_unique<Probe>(std::move(settings));
}

std::unique_ptr<calibrate::ExperimentProbe> AorProbeOf(const ExperimentFile& file, const core::Scene& model,
                                                       std::string* error) {
  auto build = [](const core::Scene& m, const objectives::AorSettings& s, uint64_t seed) {
    int64_t fixed = 0;
    return objectives::BuildAorScene(m, s, seed, &fixed);
  };
  return MakeProbe<calibrate::AorProbe, objectives::AorSettings>(file, model, ParseAorSection, build, error);
}

std::unique_ptr<calibrate::ExperimentProbe> DischargeProbeOf(const ExperimentFile& file,
                                                             const core::Scene& model, std::string* error) {
  return MakeProbe<calibrate::DischargeProbe, objectives::DischargeSettings>(
      file, model, ParseDischargeSection, objectives::BuildDischargeScene, error);
}

constexpr ExperimentKind kKinds[] = {
    {"aor", &RunAorExperiment, &AorProbeOf},
    {"discharge", &RunDischargeExperiment, &DischargeProbeOf},
    {"segregation", &RunSegregationExperiment, nullptr},
};

}  // namespace

const ExperimentKind* FindExperimentKind(const std::string& name) {
  for (const ExperimentKind& k : kKinds)
    if (name == k.name) return &k;
  return nullptr;
}

std::vector<std::string> ExperimentKindNames() {
  std::vector<std::string> names;
  for (const ExperimentKind& k : kKinds) names.push_back(k.name);
  return names;
}

}  // namespace demcal::workflow
