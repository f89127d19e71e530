#include "workflow/reproduce/calibration_steps.h"

#include <functional>
#include <sstream>

#include "objectives/farm/farm.h"

namespace demcal::workflow {

bool RunCalibrationSteps(const ReproduceContext& ctx, const std::vector<CalibrationStep>& steps,
                         std::vector<CalibrationOutcome>* outcomes, std::string* error) {
  outcomes->assign(steps.size(), CalibrationOutcome{});
  if (ctx.calibrations_in_sequence || steps.size() < 2) {
    for (size_t k = 0; k < steps.size(); ++k)
      if (!RunCalibrationStep(ctx, steps[k], &(*outcomes)[k], error)) return false;
    return true;
  }
  // Each step writes only its own log, outcome and error: the threads share nothing else.
  std::vector<std::ostringstream> logs(steps.size());
  std::vector<ReproduceContext> contexts(steps.size(), ctx);
  std::vector<std::string> errors(steps.size());
  std::vector<char> ok(steps.size(), 0);
  std::vector<std::function<void()>> tasks;
  for (size_t k = 0; k < steps.size(); ++k) {
    contexts[k].log = &logs[k];
    tasks.push_back(
        [&, k] { ok[k] = RunCalibrationStep(contexts[k], steps[k], &(*outcomes)[k], &errors[k]); });
  }
  objectives::farm::RunGathered(tasks);
  for (const std::ostringstream& log : logs) *ctx.log << log.str();
  for (size_t k = 0; k < steps.size(); ++k)
    if (!ok[k]) return *error = errors[k], false;
  return true;
}

}  // namespace demcal::workflow
