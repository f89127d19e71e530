// The segregation-heap room's entry in the experiment registry (not a calibration target: its
// observables are the pipeline's outputs, not fitted).
#include "experiments/common/kind_support.h"
#include "experiments/segregation/segregation_runner.h"
#include "experiments/segregation/segregation_section.h"

namespace demcal::workflow {

extern const ExperimentKind kSegregationExperiment = {
    "segregation", "segregation heap", &RunTyped<SegregationResult, &RunSegregationExperiment>,
    nullptr,
    &CheckSection<objectives::SegregationSettings, ParseSegregationSection>};

}  // namespace demcal::workflow
