#pragma once
// Calibration steps that do not wait on each other (stage 1's species, stage 3's coating
// levels), run together: each step on a thread of its own, their evaluator batches meeting at
// the farm's barrier (objectives::farm::RunGathered), so one farm batch holds a round of every
// step's runs and the ranks (or local threads) fill with all of them instead of one step's
// candidate × replicates. Each step keeps its own folder, study.json and journal; its outcome is
// the one it has run alone, bit for bit (same candidates, same seeds: a step's runs depend on
// its own results only). Each step's log lines go to the log as they end, prefixed with the
// step's folder name (tagged_log.h), so progress stays live while the steps run.
//
// ctx.calibrations_in_sequence runs them one after another instead (the reference the test
// compares with; `demcal reproduce --calibrations-in-sequence`).
//
//   std::vector<CalibrationOutcome> outcomes;
//   if (!RunCalibrationSteps(ctx, steps, &outcomes, &error)) return false;
#include <string>
#include <vector>

#include "workflow/reproduce/calibration_step.h"

namespace demcal::workflow {

// outcomes[k] is steps[k]'s. False (with the first failing step's error, in step order) as
// RunCalibrationStep; run together, the steps after a failing one have run too.
bool RunCalibrationSteps(const ReproduceContext& ctx, const std::vector<CalibrationStep>& steps,
                         std::vector<CalibrationOutcome>* outcomes, std::string* error);

}  // namespace demcal::workflow
