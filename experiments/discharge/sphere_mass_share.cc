#include "experiments/discharge/sphere_mass_share.h"

#include <algorithm>

namespace demcal::objectives {

std::vector<double> SphereMassShares(const core::Particles& p) {
  int bodies = 0;
  for (size_t i = 0; i < p.Size(); ++i) bodies = std::max(bodies, p.body[i] + 1);
  std::vector<int> members(bodies, 0);
  for (size_t i = 0; i < p.Size(); ++i)
    if (p.body[i] >= 0) ++members[p.body[i]];
  std::vector<double> share(p.Size());
  for (size_t i = 0; i < p.Size(); ++i) share[i] = p.body[i] >= 0 ? p.mass_kg[i] / members[p.body[i]] : p.mass_kg[i];
  return share;
}

}  // namespace demcal::objectives
