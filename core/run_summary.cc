#include "core/run_summary.h"

#include <sstream>

namespace demcal::core {

const char* TerminationName(Termination t) {
  switch (t) {
    case Termination::kOk: return "ok";
    case Termination::kInvalidScene: return "invalid_scene";
    case Termination::kNonFinite: return "non_finite";
    case Termination::kEnergyBlowUp: return "energy_blow_up";
    case Termination::kParticlesLost: return "particles_lost";
    case Termination::kWallTimeExceeded: return "wall_time_exceeded";
  }
  return "unknown";
}

std::string RunSummary::BriefReport() const {
  std::ostringstream os;
  os << TerminationName(termination) << ": " << message << " (" << steps << " steps, "
     << simulated_time_s << " s simulated, " << wall_time_s << " s wall, " << particles
     << " particles)";
  return os.str();
}

}  // namespace demcal::core
