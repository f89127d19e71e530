#pragma once
// SphereMassShares: the mass each sphere of a simulation stands for in a sum over spheres — its
// own for a free sphere; for a member of a clump, the clump's mass divided by the clump's member
// count (every member carries the whole clump's mass, because its contacts see the clump's m*:
// core/bodies/clumps.cc). Summing Particles::mass_kg instead counts an n-sphere clump n times: a
// 3-sphere chain reported a 3× mass flow and bulk density. Pure function, thread-safe.
//
//   const std::vector<double> share = SphereMassShares(sim.particles());
//   for (size_t i ...) mass += share[i];
#include <vector>

#include "core/bodies/particles.h"

namespace demcal::objectives {

std::vector<double> SphereMassShares(const core::Particles& particles);

}  // namespace demcal::objectives
