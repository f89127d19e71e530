#include "diagnose/dem/replicate_pool.h"

#include <algorithm>
#include <cmath>

namespace demcal::diagnose {

ReplicatePool::ReplicatePool(size_t targets)
    : n_(targets), squares_(targets, 0.0), dof_(targets, 0), cross_(targets * targets) {}

void ReplicatePool::Add(const std::vector<std::vector<double>>& values,
                        const std::vector<int>& group) {
  const size_t n = std::min({n_, values.size(), group.size()});
  for (size_t k = 0; k < n; ++k) {
    // In the arithmetic's order of the pooling this replaced, so that the spreads stay the same
    // to the last bit (a refit's path follows them).
    std::vector<double> v;
    for (double x : values[k])
      if (std::isfinite(x)) v.push_back(x);
    if (v.size() < 2) continue;
    double mean = 0, squares = 0;
    for (double x : v) mean += x / v.size();
    for (double x : v) squares += (x - mean) * (x - mean);
    squares_[k] += squares;
    dof_[k] += static_cast<int>(v.size()) - 1;
  }
  for (size_t k = 0; k < n; ++k)
    for (size_t l = k + 1; l < n; ++l) {
      if (group[k] < 0 || group[k] != group[l]) continue;
      const std::vector<double>& x = values[k];
      const std::vector<double>& y = values[l];
      double mx = 0, my = 0;
      int m = 0;
      for (size_t j = 0; j < x.size() && j < y.size(); ++j)
        if (std::isfinite(x[j]) && std::isfinite(y[j])) mx += x[j], my += y[j], ++m;
      if (m < 2) continue;
      mx /= m, my /= m;
      Cross& c = cross_[k * n_ + l];
      for (size_t j = 0; j < x.size() && j < y.size(); ++j)
        if (std::isfinite(x[j]) && std::isfinite(y[j])) {
          c.xy += (x[j] - mx) * (y[j] - my);
          c.xx += (x[j] - mx) * (x[j] - mx);
          c.yy += (y[j] - my) * (y[j] - my);
        }
      c.dof += m - 1;
    }
}

double ReplicatePool::Spread(size_t k) const {
  return k < n_ && dof_[k] > 0 ? std::sqrt(squares_[k] / dof_[k]) : -1;
}

const ReplicatePool::Cross* ReplicatePool::Pair(size_t k, size_t l) const {
  if (k == l || k >= n_ || l >= n_) return nullptr;
  return &cross_[std::min(k, l) * n_ + std::max(k, l)];
}

int ReplicatePool::CorrelationDof(size_t k, size_t l) const {
  const Cross* c = Pair(k, l);
  return c ? c->dof : 0;
}

double ReplicatePool::Correlation(size_t k, size_t l) const {
  const Cross* c = Pair(k, l);
  if (!c || c->dof < kMinCorrelationDof || !(c->xx > 0 && c->yy > 0)) return 0;
  return c->xy / std::sqrt(c->xx * c->yy);
}

}  // namespace demcal::diagnose
