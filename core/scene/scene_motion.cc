// Derived motion checks of Scene::IsValid: each speed may be inside kSpeed while the scene makes
// no sense with it, because what matters is how far a body travels in one time step
// (kMaxStepTravelRadii, core/limits/physical_limits.h), and whether a moving factory region
// stays where particles can be inserted.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/scene/field_checker.h"
#include "core/scene/scene.h"

namespace demcal::core {
namespace {

struct StepScale {
  double dt_s = 0;        // the time step the run will use
  double radius_m = 0;    // the smallest particle radius
  double fall_m_s = 0;    // speed gained by a free fall through the domain along gravity
  double fall_height_m = 0;
};

// Speed `v0` plus a free fall: the largest speed a body starting at v0 reaches before it can
// leave the domain (energy: v² = v0² + 2 |g| H).
double WorstSpeed(double v0, const StepScale& k) { return std::hypot(v0, k.fall_m_s); }

void CheckTravel(const std::string& field, double v0, bool falls, const StepScale& k,
                 FieldChecker& c) {
  const double v = falls ? WorstSpeed(v0, k) : v0;
  const double travel = v * k.dt_s;
  if (!c.ok() || travel <= limits::kMaxStepTravelRadii * k.radius_m) return;
  std::ostringstream os;
  os << "field '" << field << "': a speed of " << v0 << " m/s";
  if (falls && k.fall_m_s > 0)
    os << " (" << v << " m/s after a free fall of " << k.fall_height_m
       << " m through the domain along gravity)";
  os << " travels " << travel << " m in one time step of " << k.dt_s
     << " s, more than " << limits::kMaxStepTravelRadii << " × the smallest particle radius "
     << k.radius_m << " m, so bodies would pass through one another; lower the speed (or "
     << "gravity), or the time step (time.rayleigh_fraction)";
  c.Fail(os.str());
}

void CheckSpin(const std::string& field, const Vec3& omega, const StepScale& k, FieldChecker& c) {
  const double turn = Norm(omega) * k.dt_s;  // radians per step: a surface point moves turn × r
  if (!c.ok() || turn <= limits::kMaxStepTravelRadii) return;
  std::ostringstream os;
  os << "field '" << field << "': a spin of " << Norm(omega) << " rad/s turns a particle by "
     << turn << " rad in one time step of " << k.dt_s << " s (its surface moves more than "
     << limits::kMaxStepTravelRadii << " × its radius); lower the spin or the time step";
  c.Fail(os.str());
}

// A factory region translated by region_velocity_m_s while the factory is active must stay
// inside the domain, as it must at its start.
void CheckRegionTravel(const Scene& s, size_t i, FieldChecker& c) {
  const FactorySpec& f = s.factories[i];
  const double moving = std::max(0.0, std::min(f.end_s, s.time.duration_s) - f.start_s);
  const Vec3 shift = f.region_velocity_m_s * moving;
  for (int a = 0; a < 3 && c.ok(); ++a) {
    const double lo = f.region.min_m[a] + shift[a], hi = f.region.max_m[a] + shift[a];
    if (lo >= s.domain_min_m[a] && hi <= s.domain_max_m[a]) continue;
    std::ostringstream os;
    os << "field 'factories[" << i << "].region_velocity_m_s' moves the region by " << Norm(shift)
       << " m over its " << moving << " s of insertion, to [" << lo << ", " << hi
       << "] m along " << "xyz"[a] << ", outside the domain [" << s.domain_min_m[a] << ", "
       << s.domain_max_m[a] << "] m; particles would be inserted where none can stay";
    c.Fail(os.str());
  }
}

}  // namespace

void CheckSceneMotion(const Scene& s, FieldChecker& c) {
  if (s.time.force_timestep) return;  // the user insists on the step (physical_limits.h)
  StepScale k;
  k.dt_s = TimeStep(s);
  k.radius_m = 0.5 * s.MinDiameter();
  if (!(k.dt_s > 0) || !std::isfinite(k.dt_s) || !(k.radius_m > 0) || !std::isfinite(k.radius_m))
    return;  // no particle species: nothing moves
  const double g = Norm(s.gravity_m_s2);
  if (g > 0) {
    for (int a = 0; a < 3; ++a)
      k.fall_height_m +=
          std::abs(s.gravity_m_s2[a]) / g * (s.domain_max_m[a] - s.domain_min_m[a]);
    k.fall_m_s = std::sqrt(2 * g * k.fall_height_m);
  }
  CheckTravel("gravity_m_s2", 0, true, k, c);
  for (size_t i = 0; i < s.particles.size(); ++i) {
    const std::string f = "particles[" + std::to_string(i) + "]";
    CheckTravel(f + ".velocity_m_s", Norm(s.particles[i].velocity_m_s), !s.particles[i].fixed, k,
                c);
    CheckSpin(f + ".angular_velocity_rad_s", s.particles[i].angular_velocity_rad_s, k, c);
  }
  for (size_t i = 0; i < s.fills.size(); ++i)
    CheckTravel("fills[" + std::to_string(i) + "].velocity_m_s", Norm(s.fills[i].velocity_m_s),
                true, k, c);
  for (size_t i = 0; i < s.factories.size(); ++i) {
    CheckTravel("factories[" + std::to_string(i) + "].velocity_m_s",
                Norm(s.factories[i].velocity_m_s), true, k, c);
    CheckRegionTravel(s, i, c);
  }
  for (size_t i = 0; i < s.walls.size(); ++i)
    CheckTravel("walls[" + std::to_string(i) + "].velocity_m_s", Norm(s.walls[i].velocity_m_s),
                false, k, c);
}

}  // namespace demcal::core
