#include "objectives/common/settled_run.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "objectives/common/settle_eta.h"
#include "objectives/common/surface_change.h"

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
  // Expected end for the progress display: the pour plus a short settle, then followed by the
  // kinetic energy's decay (settle_eta.h).
  SettleEta eta(earliest, criteria.expected_end_s > 0 ? criteria.expected_end_s : earliest + 0.3,
                criteria.specific_kinetic_J_kg, criteria.max_time_s);
  bool settled = false;
  SurfaceGrid window_start;
  double window_start_s = -1;
  int quiet_windows = 0;  // consecutive windows below surface_change_d
  core::Simulation::Observer observer;
  observer.every_steps =
      std::max<int64_t>(1, std::llround(criteria.check_interval_s / sim.timestep_s()));
  observer.callback = [&](const core::Simulation& s) {
    if (s.time_s() < earliest) {
      if (progress) progress(s.time_s(), eta.ExpectedEndS(s.time_s(), NAN));
      return true;
    }
    result.specific_kinetic_J_kg = SpecificKineticEnergy(s);
    if (progress) progress(s.time_s(), eta.ExpectedEndS(s.time_s(), result.specific_kinetic_J_kg));
    if (result.specific_kinetic_J_kg < criteria.specific_kinetic_J_kg) {
      result.settled_by = "kinetic_energy";
      return !(settled = true);
    }
    if (!(criteria.surface_window_s > 0)) return true;
    const bool first = window_start_s < 0;
    if (!first && s.time_s() - window_start_s < criteria.surface_window_s - 1e-12) return true;
    const double d = MeanMovingDiameter(s);
    SurfaceGrid now = MovingSurface(s, 2 * d);
    if (!first) {
      result.surface_change_d = MeanSurfaceChange(window_start, now, d) / d;
      quiet_windows = result.surface_change_d < criteria.surface_change_d ? quiet_windows + 1 : 0;
    }
    window_start = std::move(now);
    window_start_s = s.time_s();
    if (quiet_windows >= 2) {
      result.settled_by = "surface";
      settled = true;
    }
    return !settled;
  };
  result.run = sim.Run(std::max(0.0, criteria.max_time_s - sim.time_s()), observer);
  result.settle_time_s = sim.time_s();
  result.factory_warnings = sim.FactoryRateWarnings();
  if (!result.run.ok()) {
    result.status = core::TerminationName(result.run.termination);
    result.message = result.run.message;
  } else if (!settled) {
    std::ostringstream os;
    os << "not settled after " << criteria.max_time_s << " s: specific kinetic energy "
       << result.specific_kinetic_J_kg << " J/kg >= " << criteria.specific_kinetic_J_kg << " J/kg";
    if (criteria.surface_window_s > 0 && result.surface_change_d >= 0)
      os << ", surface change " << result.surface_change_d << " d per " << criteria.surface_window_s
         << " s >= " << criteria.surface_change_d << " d";
    result.status = "not_settled";
    result.message = os.str();
  }
  return result;
}

}  // namespace demcal::objectives
