#include "calibrate/candidate_evaluator.h"

#include <cmath>

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

}  // namespace demcal::calibrate
