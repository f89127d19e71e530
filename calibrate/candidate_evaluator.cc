#include "calibrate/candidate_evaluator.h"

#include <cmath>
#include <string_view>

namespace demcal::calibrate {

bool TargetValue::ok() const {
  return status == "ok" && replicates >= 1 && std::isfinite(mean) && std::isfinite(sem) && sem >= 0;
}

bool CandidateResult::ok() const {
  if (status != "ok" || targets.empty()) return false;
  for (const TargetValue& t : targets)
    if (!t.ok()) return false;
  return true;
}

namespace {
constexpr std::string_view kInfeasiblePrefix = "infeasible: ";
}  // namespace

std::string InfeasibleStatus(const std::string& why) {
  return std::string(kInfeasiblePrefix) + why;
}

bool IsInfeasibleStatus(const std::string& status) {
  return status.rfind(kInfeasiblePrefix, 0) == 0;
}

}  // namespace demcal::calibrate
