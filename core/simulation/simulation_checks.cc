// Simulation::Check: the periodic health checks of a run (non-finite state, particles leaving
// the domain, mechanical energy growing without input). Each failure names the particle, the
// time and the likely cause.
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <limits>
#include <sstream>

#include "core/simulation/simulation.h"

namespace demcal::core {

Termination Simulation::Check(std::string* message) const {
  const Particles& p = system_.spheres;
  Vec3 lo = scene_.domain_min_m, hi = scene_.domain_max_m;
  for (int a = 0; a < 3; ++a)  // periodic axes wrap instead of losing particles; with sinks,
    // a particle outside the domain is removed at the next sink pass (not a failure)
    if (scene_.periodic[a] || !scene_.sinks.empty())
      lo[a] = -std::numeric_limits<double>::infinity(), hi[a] = -lo[a];
  struct Found { int64_t non_finite = -1, outside = -1; };
  const Found found = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, p.Size()), Found{},
      [&](const auto& range, Found f) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          const Vec3& x = p.position_m[i];
          if (f.non_finite < 0 && (!IsFinite(x) || !IsFinite(p.velocity_m_s[i]) ||
                                   !IsFinite(p.angular_velocity_rad_s[i])))
            f.non_finite = static_cast<int64_t>(i);
          if (f.outside < 0 && (x.x < lo.x || x.y < lo.y || x.z < lo.z || x.x > hi.x ||
                                x.y > hi.y || x.z > hi.z))
            f.outside = static_cast<int64_t>(i);
        }
        return f;
      },
      [](Found a, Found b) {
        if (a.non_finite < 0 || (b.non_finite >= 0 && b.non_finite < a.non_finite)) a.non_finite = b.non_finite;
        if (a.outside < 0 || (b.outside >= 0 && b.outside < a.outside)) a.outside = b.outside;
        return a;
      });
  std::ostringstream os;
  if (found.non_finite >= 0) {
    os << "particle id " << p.id[found.non_finite] << " has a non-finite position or velocity at t = "
       << time_s_ << " s (time step " << dt_ << " s too large, or invalid contact parameters)";
    *message = os.str();
    return Termination::kNonFinite;
  }
  if (found.outside >= 0) {
    const Vec3& x = p.position_m[found.outside];
    os << "particle id " << p.id[found.outside] << " left the domain at t = " << time_s_
       << " s, position (" << x.x << ", " << x.y << ", " << x.z
       << ") m; close the container with walls or enlarge 'domain'";
    *message = os.str();
    return Termination::kParticlesLost;
  }
  const double energy =
      system_.KineticEnergy() + system_.GravitationalPotential(scene_.gravity_m_s2);
  if (energy - energy_budget_J_ > 0.5 * energy_scale_J_ + 1e-30) {
    os << "mechanical energy grew from " << energy_budget_J_ << " J to " << energy
       << " J at t = " << time_s_ << " s with no energy input: the integration is unstable "
       << "(reduce the time step; it is " << dt_ << " s)";
    *message = os.str();
    return Termination::kEnergyBlowUp;
  }
  return Termination::kOk;
}

}  // namespace demcal::core
