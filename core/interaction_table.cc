#include "core/interaction_table.h"

#include <cmath>
#include <numbers>

namespace demcal::core {

double BetaFromRestitution(double e) {
  if (e >= 1.0) return 0.0;
  const double l = std::log(e);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

InteractionTable::InteractionTable(const std::vector<Material>& materials,
                                   const std::vector<PairParameters>& pairs)
    : n_(static_cast<int>(materials.size())), resolved_(pairs.size()) {
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < n_; ++j) {
      const Material& a = materials[i];
      const Material& b = materials[j];
      const PairParameters& p = pairs[i * n_ + j];
      const double inv_e = (1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus_Pa +
                           (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus_Pa;
      const double inv_g = 2 * (2 - a.poisson_ratio) * (1 + a.poisson_ratio) / a.youngs_modulus_Pa +
                           2 * (2 - b.poisson_ratio) * (1 + b.poisson_ratio) / b.youngs_modulus_Pa;
      resolved_[i * n_ + j] = {1.0 / inv_e,          1.0 / inv_g,         BetaFromRestitution(p.restitution),
                               p.sliding_friction,   p.rolling_friction,  p.interfacial_energy_J_m2};
    }
  }
}

}  // namespace demcal::core
