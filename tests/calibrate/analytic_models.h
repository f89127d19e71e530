#pragma once
// Analytic stand-ins for DEM in optimiser and covariance tests: seeded Gaussian noise, a
// recorder of the batches an optimiser asks for, and a linear multi-target CandidateEvaluator
// (observable_k = offset_k + Σ slope_kj θ_j, plus a simulation-noise offset drawn once per seed:
// common random numbers, as replicate seeds give).
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "calibrate/candidate_evaluator.h"
#include "calibrate/optimiser.h"
#include "core/math/random.h"

namespace demcal::calibrate::testing {

// Standard normal number k of stream `seed` (Box–Muller).
inline double Normal(uint64_t seed, int k) {
  core::Rng rng(seed * 1000003 + static_cast<uint64_t>(k));
  const double u1 = 1.0 - rng.Uniform(), u2 = rng.Uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.141592653589793 * u2);
}

// Wraps a one-point trial; records every batch asked for.
struct Recorder {
  std::function<TrialResult(const std::vector<double>&)> trial;
  std::vector<std::vector<std::vector<double>>> batches;
  BatchTrialFunction Function() {
    return [this](const std::vector<std::vector<double>>& units) {
      batches.push_back(units);
      std::vector<TrialResult> out;
      for (const auto& u : units) out.push_back(trial(u));
      return out;
    };
  }
  std::vector<std::vector<double>> Points() const {
    std::vector<std::vector<double>> all;
    for (const auto& b : batches) all.insert(all.end(), b.begin(), b.end());
    return all;
  }
};

// One parameter against several noise-free targets r_k = 4 (u − 0.5) + b_k. With offsets b of
// mean 0 the least-squares u is 0.5, χ²_min = Σ b², σ_u = 1 / sqrt(16 m): a model where a first
// joint match can lie far from the estimate (TrialResult::Settled).
inline TrialResult OffsetTargets(const std::vector<double>& b, const std::vector<double>& u) {
  TrialResult t{true, {}, std::vector<double>(b.size(), 0.0)};
  for (double bk : b) t.residuals.push_back(4 * (u[0] - 0.5) + bk);
  return t;
}

class LinearTargets final : public CandidateEvaluator {
 public:
  std::vector<double> offset;              // per target
  std::vector<std::vector<double>> slope;  // per target, per parameter (per SI unit)
  std::vector<double> sem;                 // reported simulation sem per target
  uint64_t seed = 1;                       // the simulation-noise offsets
  double nan_above = 1e300;                // theta[0] above this: the mean is NaN (a bug upstream)
  // true: each candidate draws its own noise (independent runs, as without common random
  // numbers), so finite differences of the means are noisy too.
  bool independent_noise = false;
  // true: AddReplicates answers, as n runs would: sem·sqrt(3/n) (3 replicates per evaluation)
  // with a fresh draw per n.
  bool replicable = false;
  std::vector<size_t> batch_sizes;
  int replicate_calls = 0;

  double Exact(size_t k, const std::vector<double>& theta) const {
    double y = offset[k];
    for (size_t j = 0; j < theta.size(); ++j) y += slope[k][j] * theta[j];
    return y;
  }
  std::vector<CandidateResult> EvaluateBatch(const std::vector<std::vector<double>>& p) override {
    batch_sizes.push_back(p.size());
    std::vector<CandidateResult> out;
    for (const auto& theta : p) out.push_back(Result(theta, 3));
    return out;
  }
  std::optional<CandidateResult> AddReplicates(const std::vector<double>& theta,
                                               int replicates) override {
    if (!replicable) return std::nullopt;
    ++replicate_calls;
    CandidateResult c = Result(theta, replicates);
    c.replicates_run = replicates - 3;  // the first 3 are reused
    return c;
  }

 private:
  CandidateResult Result(const std::vector<double>& theta, int replicates) const {
    CandidateResult c;
    uint64_t stream = seed;
    if (independent_noise)
      for (double t : theta) stream = stream * 1099511628211ull + static_cast<uint64_t>(std::llround(t * 1e9));
    if (replicates != 3) stream = stream * 31 + static_cast<uint64_t>(replicates);
    for (size_t k = 0; k < offset.size(); ++k) {
      const double s = sem[k] * std::sqrt(3.0 / replicates);
      c.targets.push_back({Exact(k, theta) + s * Normal(stream, static_cast<int>(k)), s, replicates});
    }
    if (theta[0] > nan_above) c.targets[0].mean = std::nan("");
    c.replicates_run = replicates;
    return c;
  }
};

}  // namespace demcal::calibrate::testing
