#include "diagnose/loop/base_noise.h"

#include <map>
#include <tuple>

namespace demcal::diagnose {

NoisyChi2 BaseChi2(const std::vector<Observation>& at) {
  NoisyChi2 c{0, 0};
  // Per simulated quantity (mean, sem, scatter): the sum of 2·r_i·u_i of the rows reading it.
  std::map<std::tuple<double, double, double>, double> shared;
  for (const Observation& o : at) {
    const double r = o.Residual();
    c.chi2 += r * r;
    if (o.sem > 0) shared[{o.simulated, o.sem, o.scatter}] += 2 * r * o.sem / o.Sigma();
  }
  double var = 0;
  for (const auto& [key, sum] : shared) var += sum * sum;
  c.noise_sd = std::sqrt(var);
  return c;
}

}  // namespace demcal::diagnose
