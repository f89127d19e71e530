#include "core/simulation/run_summary.h"

#include <cmath>
#include <sstream>
#include <utility>

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

PhaseTimes& PhaseTimes::operator-=(const PhaseTimes& o) {
  integrate_s -= o.integrate_s, insert_s -= o.insert_s, rebuild_check_s -= o.rebuild_check_s;
  rebuild_s -= o.rebuild_s, forces_s -= o.forces_s, checks_s -= o.checks_s;
  return *this;
}

double PhaseTimes::Total() const {
  return integrate_s + insert_s + rebuild_check_s + rebuild_s + forces_s + checks_s;
}

std::string PhaseTimes::Report() const {
  const double total = Total() > 0 ? Total() : 1;
  std::ostringstream os;
  os.precision(3);
  const std::pair<const char*, double> phases[] = {
      {"integrate", integrate_s}, {"insert", insert_s}, {"rebuild check", rebuild_check_s},
      {"rebuild", rebuild_s},     {"forces", forces_s}, {"checks", checks_s}};
  for (const auto& [name, t] : phases)
    os << (name == phases[0].first ? "" : ", ") << name << " " << t << " s ("
       << static_cast<int>(std::lround(100 * t / total)) << " %)";
  return os.str();
}

std::string RunSummary::BriefReport() const {
  std::ostringstream os;
  os << TerminationName(termination) << ": " << message << " (" << steps << " steps, "
     << simulated_time_s << " s simulated, " << wall_time_s << " s wall, " << particles
     << " particles)";
  return os.str();
}

}  // namespace demcal::core
