#pragma once
// The `demcal experiment segregation` runner (segregation_runner.cc): replicates of the file's
// run, their tables and pictures, DIR/result.json written from the returned SegregationResult
// (segregation_result.h).
#include <ostream>

#include "experiments/common/experiment_runner.h"
#include "experiments/segregation/segregation_result.h"

namespace demcal::workflow {

SegregationResult RunSegregationExperiment(const ExperimentFile& file,
                                           const ExperimentContext& context, std::ostream& log);

}  // namespace demcal::workflow
