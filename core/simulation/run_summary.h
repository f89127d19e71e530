#pragma once
// RunSummary: how a simulation run ended and what it cost. A failed run is a normal outcome
// (the calibrator treats it as an infeasible sample), never an exception or a crash.
#include <cstdint>
#include <string>

#include "core/neighbours/sweep_balance.h"

namespace demcal::core {

enum class Termination {
  kOk,                // ran for the requested time (or the observer stopped it)
  kInvalidScene,      // the scene failed validation; nothing ran
  kNonFinite,         // a position, velocity or force became NaN/Inf
  kEnergyBlowUp,      // kinetic energy exceeded what gravity and the initial state can supply
  kParticlesLost,     // a particle left the domain box
  kWallTimeExceeded,  // the run's wall-time budget ran out
};

// Stable lower-case names used in summary.json: ok, invalid_scene, non_finite, ...
const char* TerminationName(Termination t);

// Wall time of a run by phase of the time step, s (steady clock, a few ns per reading).
struct PhaseTimes {
  double integrate_s = 0;      // both half kicks and the drift (clumps and periodic wrap too)
  double insert_s = 0;         // factories
  double rebuild_check_s = 0;  // has any particle moved half the skin?
  double rebuild_s = 0;        // re-sort, neighbour search, history and wall-candidate transfer
  double forces_s = 0;         // contact force sweep (pairs and walls), wall work
  double checks_s = 0;         // NaN / domain / energy checks and the observer

  PhaseTimes& operator-=(const PhaseTimes& o);
  double Total() const;
  // "integrate 0.31 s (12 %), ... " in the order above.
  std::string Report() const;
};

// Particles the steps' neighbour rebuilds searched (an incremental rebuild searches only those
// that moved, NeighbourList::LastMovers) and the moving particles at those rebuilds, summed.
struct RebuildSearch {
  uint64_t searched = 0;
  uint64_t moving = 0;
  RebuildSearch& operator-=(const RebuildSearch& o) {
    searched -= o.searched, moving -= o.moving;
    return *this;
  }
};

struct RunSummary {
  Termination termination = Termination::kInvalidScene;
  std::string message = "Run was not called";
  int64_t steps = 0;
  double simulated_time_s = 0;
  double wall_time_s = 0;
  int64_t particles = 0;
  double timestep_s = 0;
  double final_kinetic_energy_J = 0;
  uint64_t neighbour_rebuilds = 0;  // during this Run() call
  RebuildSearch rebuild_search;     // during this Run() call
  PhaseTimes phases;                // during this Run() call
  SweepBalance sweep_balance;       // during this Run() call

  bool ok() const { return termination == Termination::kOk; }
  std::string BriefReport() const;
};

}  // namespace demcal::core
