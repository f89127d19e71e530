#pragma once
// RunUntilSettled: runs a poured experiment until the feed has finished and the particles have
// come to rest, or until a time limit. Settled is either of:
//  * "kinetic_energy": the mean specific kinetic energy is below a threshold (physics of a
//    static heap; an absolute figure, so a large heap that still creeps may never meet it);
//  * "surface" (scale-free): the heap surface no longer changes — over two consecutive windows
//    of surface_window_s the top of the moving grains per square cell of two mean diameters
//    (surface_change.h) moved on average less than surface_change_d mean diameters.
// A run that does not settle in time, or that fails in the engine, is a normal outcome reported
// in the status, never an exception.
#include <functional>
#include <string>
#include <vector>

#include "core/simulation/simulation.h"

namespace demcal::objectives {

struct SettleCriteria {
  double feed_end_s = 0;                 // the pour has finished by then
  double min_settle_s = 0.05;            // at least this long after feed_end_s
  double specific_kinetic_J_kg = 1e-5;   // KE / mass of the moving particles below this
  double check_interval_s = 0.01;        // of simulated time
  double max_time_s = 10;                // give up (status "not_settled")
  // The end the progress display assumes until the pour is over (0: the pour's end + 0.3 s,
  // a heap poured straight onto its base).
  double expected_end_s = 0;
  // The surface criterion (0: off). 0.1 s is ~7 free-fall times √(d/g) of a 2 mm grain, so a
  // window sees any avalanche still running; 0.02 d per window: on a flank ~30 d long that
  // tilts a fitted repose angle by < 0.04° per window, far below the replicate spread of the
  // angle (0.5–1°), while grains that only rattle in place (the creep of a large heap at
  // 1–4e-5 J/kg) leave the surface where it is.
  double surface_window_s = 0.1;
  double surface_change_d = 0.02;
};

struct SettleResult {
  std::string status = "ok";   // "ok", "not_settled", or a core termination name
  std::string message;
  core::RunSummary run;
  double settle_time_s = 0;     // simulated time when the criterion was met
  double specific_kinetic_J_kg = 0;
  std::string settled_by;       // "kinetic_energy" or "surface" when ok
  double surface_change_d = -1; // of the last full surface window (mean diameters; −1: none)
  // Simulation::FactoryRateWarnings at the end: a feed that fell behind its nominal rate.
  std::vector<std::string> factory_warnings;
  bool ok() const { return status == "ok"; }
};

// Initialises `sim` for a run; false, with status "invalid_scene" and the reason in *result,
// when the scene cannot start.
bool InitializeSettledRun(core::Simulation& sim, SettleResult* result);

// progress(simulated_time_s, expected_end_s) is called every check (may be empty).
using ProgressCallback = std::function<void(double, double)>;

SettleResult RunUntilSettled(core::Simulation& sim, const SettleCriteria& criteria,
                             const ProgressCallback& progress);

// Mean specific kinetic energy of the moving bodies: total translational + rotational kinetic
// energy over their total mass (J/kg; fixed spheres excluded, a clump counted once); 0 without
// moving mass. A scale for the threshold: a grain of diameter d at rest on a heap moves far less
// than d per free-fall time √(d/g), i.e. ½v² ≪ ½ g d (≈ 0.01 J/kg for 2 mm grains), so 1e-5 J/kg
// (v ≈ 4.5 mm/s rms) is strict. NaN for a blown-up state, which never counts as settled.
double SpecificKineticEnergy(const core::Simulation& sim);

}  // namespace demcal::objectives
