#include "core/scene/scene_overlaps.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

namespace demcal::core {

std::string ExplicitOverlapError(const Scene& s) {
  const size_t n = s.particles.size();
  std::vector<double> radius(n);
  for (size_t i = 0; i < n; ++i) {
    const ParticleSpec& p = s.particles[i];
    if (p.species < 0 || p.species >= static_cast<int>(s.species.size())) return "";
    radius[i] = 0.5 * (p.diameter_m > 0 ? p.diameter_m : s.species[p.species].size.MinDiameter());
  }
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return s.particles[a].position_m.x < s.particles[b].position_m.x;
  });
  const double reach = n ? 2 * *std::max_element(radius.begin(), radius.end()) : 0;
  for (size_t a = 0; a < n; ++a) {
    const size_t i = order[a];
    const Vec3& xi = s.particles[i].position_m;
    for (size_t b = a + 1; b < n && s.particles[order[b]].position_m.x - xi.x <= reach; ++b) {
      const size_t j = order[b];
      const double d = Norm(s.particles[j].position_m - xi);
      if (d >= std::max(radius[i], radius[j])) continue;
      std::ostringstream os;
      os << "field 'particles[" << std::min(i, j) << "]' and 'particles[" << std::max(i, j)
         << "]': centres " << d << " m apart, inside one another (radii " << radius[i] << " and "
         << radius[j] << " m); explicit particles may overlap by less than the smaller radius";
      return os.str();
    }
  }
  return "";
}

}  // namespace demcal::core
