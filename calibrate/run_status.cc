#include "calibrate/run_status.h"

#include <algorithm>

#include "core/simulation/run_summary.h"

namespace demcal::calibrate {

const std::vector<std::string>& RunStatusNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    using core::Termination;
    for (Termination t : {Termination::kOk, Termination::kInvalidScene, Termination::kNonFinite,
                          Termination::kEnergyBlowUp, Termination::kParticlesLost,
                          Termination::kWallTimeExceeded})
      n.push_back(core::TerminationName(t));
    // The experiments' own: a heap that did not settle or gave no angle (aor), a discharge
    // that jammed, left material behind or gave no metrics, a segregation funnel not emptied
    // or a heap not analysed.
    for (const char* s : {"not_settled", "no_angle", "jammed", "not_empty", "no_metrics",
                          "funnel_not_empty", "no_analysis"})
      n.push_back(s);
    return n;
  }();
  return names;
}

bool IsRunStatus(const std::string& status) {
  const std::vector<std::string>& names = RunStatusNames();
  return std::find(names.begin(), names.end(), status) != names.end();
}

}  // namespace demcal::calibrate
