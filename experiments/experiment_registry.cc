#include "experiments/experiment_registry.h"

namespace demcal::workflow {

// The rooms, each defined in experiments/<name>/<name>_kind.cc. A new experiment: its folder,
// and its line here.
extern const ExperimentKind kAorExperiment;
extern const ExperimentKind kDischargeExperiment;
extern const ExperimentKind kSegregationExperiment;

namespace {

const ExperimentKind* const kKinds[] = {&kAorExperiment, &kDischargeExperiment,
                                        &kSegregationExperiment};

}  // namespace

const ExperimentKind* FindExperimentKind(const std::string& name) {
  for (const ExperimentKind* k : kKinds)
    if (name == k->name) return k;
  return nullptr;
}

std::vector<std::string> ExperimentKindNames() {
  std::vector<std::string> names;
  for (const ExperimentKind* k : kKinds) names.push_back(k->name);
  return names;
}

std::vector<std::string> CalibratableExperimentNames() {
  std::vector<std::string> names;
  for (const ExperimentKind* k : kKinds)
    if (k->make_probe) names.push_back(k->name);
  return names;
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& n : names) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

}  // namespace demcal::workflow
