#include "diagnose/loop/base_noise.h"

#include <Eigen/Dense>

#include "diagnose/ranking/evidence.h"

namespace demcal::diagnose {

NoisyChi2 BaseChi2(const std::vector<Observation>& at) {
  const Eigen::Index n = static_cast<Eigen::Index>(at.size());
  Eigen::VectorXd r(n), u(n);
  for (Eigen::Index i = 0; i < n; ++i) r(i) = at[i].Residual(), u(i) = at[i].sem / at[i].Sigma();
  return {r.squaredNorm(),
          CorrelatedChi2NoiseSd(r, u, Eigen::VectorXd::Zero(n), 0,
                                ErrorCorrelation(Sources(at), Correlations(at), n))};
}

}  // namespace demcal::diagnose
