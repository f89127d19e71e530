#include "workflow/reproduce/calibration_steps.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>

#include "objectives/farm/farm.h"
#include "workflow/reproduce/tagged_log.h"

namespace demcal::workflow {

bool RunCalibrationSteps(const ReproduceContext& ctx, const std::vector<CalibrationStep>& steps,
                         std::vector<CalibrationOutcome>* outcomes, std::string* error) {
  outcomes->assign(steps.size(), CalibrationOutcome{});
  if (ctx.calibrations_in_sequence || steps.size() < 2) {
    for (size_t k = 0; k < steps.size(); ++k)
      if (!RunCalibrationStep(ctx, steps[k], &(*outcomes)[k], error)) return false;
    return true;
  }
  // Each step writes only its own outcome and error, and its log lines, tagged with its folder's
  // name, go to the shared log as they end (progress stays live): the threads share nothing else.
  std::mutex log_lock;
  std::vector<std::unique_ptr<TaggedLog>> tagged;
  std::vector<std::unique_ptr<std::ostream>> logs;
  std::vector<ReproduceContext> contexts(steps.size(), ctx);
  std::vector<std::string> errors(steps.size());
  std::vector<char> ok(steps.size(), 0);
  std::vector<std::function<void()>> tasks;
  for (size_t k = 0; k < steps.size(); ++k) {
    const std::string tag = std::filesystem::path(steps[k].dir).filename().string();
    tagged.push_back(std::make_unique<TaggedLog>(tag, ctx.log, &log_lock));
    logs.push_back(std::make_unique<std::ostream>(tagged.back().get()));
    contexts[k].log = logs.back().get();
    tasks.push_back(
        [&, k] { ok[k] = RunCalibrationStep(contexts[k], steps[k], &(*outcomes)[k], &errors[k]); });
  }
  objectives::farm::RunGathered(tasks);
  logs.clear();
  tagged.clear();  // writes any last line without its newline
  for (size_t k = 0; k < steps.size(); ++k)
    if (!ok[k]) return *error = errors[k], false;
  return true;
}

}  // namespace demcal::workflow
