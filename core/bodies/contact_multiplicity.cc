#include "core/bodies/contact_multiplicity.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace demcal::core {

namespace {

// Member j lies inside member i (no surface of its own to touch with); relative tolerance so
// that two coincident equal members both count.
bool Inside(const ClumpSphere& j, const ClumpSphere& i) {
  return Norm(j.centre_m - i.centre_m) + j.radius_m < i.radius_m * (1 - 1e-9);
}

}  // namespace

double ContactMultiplicity(const std::vector<ClumpSphere>& members) {
  const size_t n = members.size();
  std::vector<bool> surface(n, true);  // the member has a surface of its own
  for (size_t j = 0; j < n; ++j)
    for (size_t i = 0; i < n; ++i)
      if (i != j && Inside(members[j], members[i])) surface[j] = false;
  double most = 1;
  for (size_t i = 0; i < n; ++i) {
    if (!surface[i]) continue;
    double springs = 0;
    for (size_t j = 0; j < n; ++j) {
      if (!surface[j]) continue;
      const ClumpSphere& a = members[i];
      const ClumpSphere& b = members[j];
      const double d = Norm(b.centre_m - a.centre_m);
      const double dr = a.radius_m - b.radius_m;
      const double apart = std::sqrt(std::max(0.0, d * d - dr * dr));
      const double scale = kCoincidentSpacing * std::min(a.radius_m, b.radius_m);
      springs += std::max(0.0, 1 - apart / scale);
    }
    most = std::max(most, springs);
  }
  return most;
}

double ClumpStepFactor(const std::vector<ClumpSphere>& members, double union_volume_m3) {
  if (members.size() < 2) return 1;
  double r_min = members.front().radius_m;
  for (const ClumpSphere& m : members) r_min = std::min(r_min, m.radius_m);
  const double mass_ratio = union_volume_m3 / (4.0 / 3.0 * std::numbers::pi * r_min * r_min * r_min);
  return std::min(1.0, std::sqrt(mass_ratio) / ContactMultiplicity(members));
}

}  // namespace demcal::core
