#pragma once
// Settling criterion for a poured heap: the grains' mean specific kinetic energy (kinetic energy
// per unit mass, ½v² averaged with mass weights = total ½mv² / total mass, in J/kg) below a
// threshold. A scale for the threshold: a grain of diameter d settled on a heap moves far less
// than one diameter per free-fall time √(d/g), i.e. ½v² ≪ ½ g d; for 2 mm grains ½ g d ≈ 0.01 J/kg,
// so 1e-5 J/kg (v ≈ 4.5 mm/s rms) is a strict choice. Rotation is not counted (Grain has no
// angular velocity). Pure functions, thread-safe.
//
//   while (!IsSettled(TakeSnapshot(sim), 1e-5)) sim.Run(0.05);
#include "objectives/snapshot.h"

namespace demcal::objectives {

// Total translational kinetic energy over total mass, J/kg; 0 for no grains or no mass.
double MeanSpecificKineticEnergy(const Snapshot& snapshot);

// True when there is mass to judge and its mean specific kinetic energy is below the threshold.
// An empty snapshot (or one without mass) is not settled: there is no heap yet.
bool IsSettled(const Snapshot& snapshot, double kinetic_energy_per_mass_threshold_J_kg);

}  // namespace demcal::objectives
