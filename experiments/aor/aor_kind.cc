// The angle-of-repose room's entry in the experiment registry.
#include "experiments/aor/aor_probe.h"
#include "experiments/aor/aor_runner.h"
#include "experiments/aor/aor_section.h"
#include "experiments/common/kind_support.h"

namespace demcal::workflow {
namespace {

std::unique_ptr<calibrate::ExperimentProbe> MakeAorProbe(const ExperimentFile& file,
                                                         const core::Scene& model,
                                                         std::string* error) {
  auto build = [](const core::Scene& m, const objectives::AorSettings& s, uint64_t seed) {
    int64_t fixed = 0;
    return objectives::BuildAorScene(m, s, seed, &fixed);
  };
  return MakeProbe<calibrate::AorProbe, objectives::AorSettings>(file, model, ParseAorSection,
                                                                 build, error);
}

}  // namespace

extern const ExperimentKind kAorExperiment = {
    "aor", "angle of repose", &RunTyped<AorResult, &RunAorExperiment>, &MakeAorProbe,
    &CheckSection<objectives::AorSettings, ParseAorSection>};

}  // namespace demcal::workflow
