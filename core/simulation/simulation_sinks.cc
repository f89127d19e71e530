// Simulation: particles leaving through sinks (sink.h) and walls taken away at a time.
#include <algorithm>
#include <limits>

#include "core/simulation/simulation.h"

namespace demcal::core {

bool Simulation::RemoveSunkParticles() {
  Particles& p = system_.spheres;
  Clumps& clumps = system_.clumps;
  const bool domain_sink = sink_reports_.size() > scene_.sinks.size();
  Vec3 lo = scene_.domain_min_m, hi = scene_.domain_max_m;
  for (int a = 0; a < 3; ++a)  // periodic axes wrap instead of losing particles
    if (scene_.periodic[a]) lo[a] = -std::numeric_limits<double>::infinity(), hi[a] = -lo[a];
  const Vec3 g = scene_.gravity_m_s2;
  const double t = time_s_ + dt_;
  bool any = false;
  sphere_gone_.assign(p.Size(), 0);
  clump_gone_.assign(clumps.Size(), 0);
  // Removed bodies take their kinetic and potential energy out of the budget.
  auto take = [&](int sink, int species, double mass, double kinetic, const Vec3& x) {
    SinkReport& r = sink_reports_[sink];
    ++r.particles[species];
    r.mass_kg[species] += mass;
    r.last_removal_s = t;
    energy_budget_J_ -= kinetic - mass * Dot(g, x);
    any = true;
  };
  const size_t moving = list_.FirstFixed();  // fixed spheres are never removed
  for (size_t s = 0; s < std::min(moving, p.Size()); ++s) {
    if (p.body[s] >= 0 || p.inv_mass[s] == 0) continue;
    const int k = SinkOf(scene_.sinks, domain_sink, lo, hi, p.position_m[s]);
    if (k < 0) continue;
    sphere_gone_[s] = 1;
    take(k, p.species[s], p.mass_kg[s], p.FreeKineticEnergy(s), p.position_m[s]);
  }
  for (size_t c = 0; c < clumps.Size(); ++c) {
    const int k = SinkOf(scene_.sinks, domain_sink, lo, hi, clumps.position_m[c]);
    if (k < 0) continue;
    clump_gone_[c] = 1;
    take(k, clumps.species[c], clumps.mass_kg[c], clumps.KineticEnergy(c), clumps.position_m[c]);
  }
  if (!any) return false;
  slots_before_removal_ = p.Size();
  removal_order_ = system_.Remove(sphere_gone_, clump_gone_);
  return true;
}

bool Simulation::WallRemovedDuringStep(double time_s) {
  bool changed = false;
  for (size_t w = 0; w < walls_.size(); ++w) {
    const bool removed = time_s >= scene_.walls[w].remove_at_s;
    changed = changed || removed != walls_[w].removed;
    walls_[w].removed = removed;
  }
  return changed;
}

}  // namespace demcal::core
