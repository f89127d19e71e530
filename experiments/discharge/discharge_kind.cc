// The funnel-discharge room's entry in the experiment registry.
#include "experiments/common/kind_support.h"
#include "experiments/discharge/discharge_probe.h"
#include "experiments/discharge/discharge_runner.h"
#include "experiments/discharge/discharge_section.h"

namespace demcal::workflow {
namespace {

std::unique_ptr<calibrate::ExperimentProbe> MakeDischargeProbe(const ExperimentFile& file,
                                                               const core::Scene& model,
                                                               std::string* error) {
  return MakeProbe<calibrate::DischargeProbe, objectives::DischargeSettings>(
      file, model, ParseDischargeSection, objectives::BuildDischargeScene, error);
}

}  // namespace

extern const ExperimentKind kDischargeExperiment = {
    "discharge", "funnel discharge", &RunTyped<DischargeResult, &RunDischargeExperiment>,
    &MakeDischargeProbe,
    &CheckSection<objectives::DischargeSettings, ParseDischargeSection>};

}  // namespace demcal::workflow
