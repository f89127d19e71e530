#include "objectives/settling.h"

namespace demcal::objectives {

namespace {

double TotalMass(const Snapshot& snapshot) {
  double mass = 0;
  for (const Grain& g : snapshot.grains) mass += g.mass_kg;
  return mass;
}

}  // namespace

double MeanSpecificKineticEnergy(const Snapshot& snapshot) {
  const double mass = TotalMass(snapshot);
  if (!(mass > 0)) return 0;
  double energy = 0;
  for (const Grain& g : snapshot.grains) energy += 0.5 * g.mass_kg * core::Norm2(g.velocity_m_s);
  return energy / mass;
}

bool IsSettled(const Snapshot& snapshot, double kinetic_energy_per_mass_threshold_J_kg) {
  if (!(TotalMass(snapshot) > 0)) return false;
  // A NaN energy (a blown-up run) compares false: never settled.
  return MeanSpecificKineticEnergy(snapshot) < kinetic_energy_per_mass_threshold_J_kg;
}

}  // namespace demcal::objectives
