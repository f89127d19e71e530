#include "core/bodies/clump_size.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace demcal::core {

namespace {
constexpr int kDirections = 4096;
}

double MeanCaliperDiameter(const std::vector<ClumpSphere>& spheres) {
  if (spheres.empty()) return 0;
  const double golden_angle = std::numbers::pi * (3 - std::sqrt(5.0));
  double sum = 0;
  for (int i = 0; i < kDirections; ++i) {
    const double z = 1 - (2 * i + 1.0) / kDirections;  // equal-area bands
    const double rho = std::sqrt(1 - z * z), phi = golden_angle * i;
    const Vec3 u{rho * std::cos(phi), rho * std::sin(phi), z};
    double hi = -std::numeric_limits<double>::infinity();
    double lo = std::numeric_limits<double>::infinity();
    for (const ClumpSphere& s : spheres) {
      const double along = Dot(s.centre_m, u);
      hi = std::max(hi, along + s.radius_m);
      lo = std::min(lo, along - s.radius_m);
    }
    sum += hi - lo;
  }
  return sum / kDirections;
}

}  // namespace demcal::core
