#include "core/insertion/sink.h"

#include <cmath>
#include <numeric>

namespace demcal::core {

int64_t SinkReport::TotalParticles() const {
  return std::accumulate(particles.begin(), particles.end(), int64_t{0});
}

double SinkReport::TotalMassKg() const {
  return std::accumulate(mass_kg.begin(), mass_kg.end(), 0.0);
}

std::string SinkProblem(const SinkSpec& sink) {
  if (sink.name.empty() || sink.name == "domain")
    return ".name' must be non-empty and not 'domain' (the implicit domain sink)";
  if (sink.shape == SinkSpec::Shape::kPlane) {
    if (!IsFinite(sink.point_m)) return ".point_m' must be finite";
    if (!(std::abs(Norm(sink.normal) - 1) < 1e-9)) return ".normal' must be a unit vector";
    return "";
  }
  for (int a = 0; a < 3; ++a)
    if (!(sink.max_m[a] > sink.min_m[a]) || !std::isfinite(sink.min_m[a]) ||
        !std::isfinite(sink.max_m[a]))
      return ".max_m' must be finite and exceed 'min_m' on every axis";
  return "";
}

int SinkOf(const std::vector<SinkSpec>& sinks, bool domain_sink, const Vec3& lo, const Vec3& hi,
           const Vec3& x) {
  for (size_t k = 0; k < sinks.size(); ++k)
    if (sinks[k].Contains(x)) return static_cast<int>(k);
  if (domain_sink && (x.x < lo.x || x.y < lo.y || x.z < lo.z || x.x > hi.x || x.y > hi.y ||
                      x.z > hi.z))
    return static_cast<int>(sinks.size());
  return -1;
}

}  // namespace demcal::core
