#include "objectives/common/settled_run.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace demcal::objectives {

double SpecificKineticEnergy(const core::Simulation& sim) {
  const core::Particles& p = sim.particles();
  double mass = 0;
  // Free spheres, then each clump once (its members carry the whole clump's mass, for m*).
  for (size_t i = 0; i < p.Size(); ++i)
    if (p.inv_mass[i] > 0 && p.body[i] < 0) mass += p.mass_kg[i];
  for (double clump_kg : sim.system().clumps.mass_kg) mass += clump_kg;
  return mass > 0 ? sim.KineticEnergy() / mass : 0;
}

bool InitializeSettledRun(core::Simulation& sim, SettleResult* result) {
  std::string error;
  if (sim.Initialize(&error)) return true;
  result->status = "invalid_scene";
  result->message = error;
  return false;
}

SettleResult RunUntilSettled(core::Simulation& sim, const SettleCriteria& criteria,
                             const ProgressCallback& progress) {
  SettleResult result;
  const double earliest = criteria.feed_end_s + criteria.min_settle_s;
  // Expected end for the progress display: the pour plus a settling time of the same order.
  const double expected_end = std::min(criteria.max_time_s, earliest + 0.3);
  bool settled = false;
  core::Simulation::Observer observer;
  observer.every_steps =
      std::max<int64_t>(1, std::llround(criteria.check_interval_s / sim.timestep_s()));
  observer.callback = [&](const core::Simulation& s) {
    if (progress) progress(s.time_s(), std::max(expected_end, s.time_s()));
    if (s.time_s() < earliest) return true;
    result.specific_kinetic_J_kg = SpecificKineticEnergy(s);
    settled = result.specific_kinetic_J_kg < criteria.specific_kinetic_J_kg;
    return !settled;
  };
  result.run = sim.Run(std::max(0.0, criteria.max_time_s - sim.time_s()), observer);
  result.settle_time_s = sim.time_s();
  if (!result.run.ok()) {
    result.status = core::TerminationName(result.run.termination);
    result.message = result.run.message;
  } else if (!settled) {
    std::ostringstream os;
    os << "not settled after " << criteria.max_time_s << " s: specific kinetic energy "
       << result.specific_kinetic_J_kg << " J/kg >= " << criteria.specific_kinetic_J_kg << " J/kg";
    result.status = "not_settled";
    result.message = os.str();
  }
  return result;
}

}  // namespace demcal::objectives
