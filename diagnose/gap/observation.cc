#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

std::vector<double> Residuals(const std::vector<Observation>& observations) {
  std::vector<double> r;
  r.reserve(observations.size());
  for (const Observation& o : observations) r.push_back(o.Residual());
  return r;
}

std::vector<int> Sources(const std::vector<Observation>& observations) {
  std::vector<int> s;
  s.reserve(observations.size());
  for (const Observation& o : observations) s.push_back(o.source);
  return s;
}

std::vector<std::vector<double>> Correlations(const std::vector<Observation>& observations) {
  std::vector<std::vector<double>> c;
  c.reserve(observations.size());
  for (const Observation& o : observations) c.push_back(o.correlation);
  return c;
}

}  // namespace demcal::diagnose
