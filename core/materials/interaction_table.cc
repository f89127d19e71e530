#include "core/materials/interaction_table.h"

#include <cmath>
#include <numbers>

#include "core/contact/normal_model.h"

namespace demcal::core {

double BetaFromRestitution(double e) {
  if (e >= 1.0) return 0.0;
  const double l = std::log(e);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

ResolvedPair MakeResolvedPair(double e_star, double g_star, double beta, double mu_s, double mu_r,
                              double gamma, double cohesion_energy_density_J_m3) {
  ResolvedPair pair{e_star, g_star, beta, mu_s, mu_r, gamma, 0.0,
                    std::sqrt(4.0 * g_star / e_star), cohesion_energy_density_J_m3};
  ResolveNormalModelConstants(pair);  // what the normal laws derive from the pair
  return pair;
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
      resolved_[i * n_ + j] =
          MakeResolvedPair(1.0 / inv_e, 1.0 / inv_g, BetaFromRestitution(p.restitution),
                           p.sliding_friction, p.rolling_friction, p.interfacial_energy_J_m2,
                           p.cohesion_energy_density_J_m3);
    }
  }
}

}  // namespace demcal::core
