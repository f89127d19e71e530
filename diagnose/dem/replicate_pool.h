#pragma once
// ReplicatePool: the simulation scatter of a diagnosis's targets pooled over every evaluation,
// and the correlation of two targets' single-run values within one run.
//
// Spread (per target): Σ(n_i − 1)s_i² / Σ(n_i − 1) over the evaluations, the replicates of each
// evaluation about their own mean: packing noise depends little on the parameters, and one
// point's own spread over 2-3 replicates is too unsteady to divide by.
//
// Correlation (per pair of targets read from one run group, different observables: the angle and
// the height of one heap, the discharge time and the mass flow of one funnel): the replicates'
// deviations from their evaluation's mean, over the replicates where both targets have a value,
// pooled the same way, r = Σ dx·dy / √(Σ dx² Σ dy²) with Σ(n_i − 1) degrees of freedom. One run
// moves both values at once, so their simulated means carry correlated errors; the χ² noise
// (CorrelatedChi2NoiseSd, evidence.h) needs that correlation (docs/diagnose/ranking.md). With
// 2 replicates one evaluation gives one degree of freedom, its own correlation is ±1 and says
// nothing; pooled over the diagnosis's evaluations it is an estimate. Below kMinCorrelationDof
// degrees of freedom it is not used (0: the rows counted as independent, the formula before):
// the standard error of a sample correlation is about (1 − r²)/√dof, 0.32 at 10 for r = 0, so
// fewer pairs could not tell a correlation of 0.5 from none.
//
//   ReplicatePool pool(3);
//   pool.Add({{10.1, 9.7}, {0.011, 0.010}, {0.3, 0.4}}, {0, 0, 1});  // per target its replicates
//   pool.Spread(0); pool.Correlation(0, 1);
//
// Thread-safety: a plain value.
#include <cstddef>
#include <vector>

namespace demcal::diagnose {

constexpr int kMinCorrelationDof = 10;

class ReplicatePool {
 public:
  explicit ReplicatePool(size_t targets);
  // One evaluation: per target its replicate values in replicate order (NaN: that run gave
  // none) and its run group (targets of one group read the same runs, replicate by replicate).
  void Add(const std::vector<std::vector<double>>& values, const std::vector<int>& group);
  // Pooled single-run standard deviation; negative when no evaluation gave two values.
  double Spread(size_t k) const;
  int Dof(size_t k) const { return k < dof_.size() ? dof_[k] : 0; }
  // Pooled within-run correlation of targets k and l (k ≠ l); 0 below kMinCorrelationDof.
  double Correlation(size_t k, size_t l) const;
  int CorrelationDof(size_t k, size_t l) const;

 private:
  struct Cross {
    double xy = 0, xx = 0, yy = 0;
    int dof = 0;
  };
  const Cross* Pair(size_t k, size_t l) const;
  size_t n_;
  std::vector<double> squares_;
  std::vector<int> dof_;
  std::vector<Cross> cross_;  // k < l: at k * n + l
};

}  // namespace demcal::diagnose
