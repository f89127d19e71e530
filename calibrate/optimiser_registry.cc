#include <algorithm>
#include <cmath>
#include <utility>

#include "calibrate/chi_square.h"
#include "calibrate/optimiser.h"
#include "objectives/common/input_limits.h"

namespace demcal::calibrate {
namespace {

struct Entry {
  const char* name;
  Optimiser optimise;
};

constexpr Entry kOptimisers[] = {
    {"bracket", BracketOptimise},
    {"nlopt_bobyqa", NloptBobyqa},
    {"nlopt_cobyla", NloptCobyla},
    {"nlopt_neldermead", NloptNelderMead},
    {"ceres", CeresOptimise},
    {"differential_evolution", DifferentialEvolution},
};

// Σ residual² / (1 + noise²) within the χ²_dof quantile at kWithinNoiseProbability (for dof = 1:
// ≤ 1, the 1σ rule exactly: the quantile's bisection would blur the boundary); `precise`: every
// noise ≤ kMatchNoise.
bool ResidualsWithinNoise(const TrialResult& t, size_t dof, bool* precise) {
  *precise = true;
  if (!t.ok) return false;
  double chi2 = 0;
  for (size_t k = 0; k < t.residuals.size(); ++k) {
    const double n = k < t.noise.size() ? t.noise[k] : 0.0;
    chi2 += t.residuals[k] * t.residuals[k] / (1 + n * n);
    *precise = *precise && n <= kMatchNoise;
  }
  if (t.residuals.empty()) return true;
  const double limit = dof <= 1 ? 1.0 : ChiSquareQuantile(kWithinNoiseProbability, static_cast<double>(dof));
  return chi2 <= limit;
}

}  // namespace

bool TrialResult::WithinNoise() const {
  bool precise = false;
  return ResidualsWithinNoise(*this, residuals.size(), &precise) && precise;
}

bool TrialResult::Settled(size_t parameters) const {
  bool precise = false;
  return ResidualsWithinNoise(*this, std::min(parameters, residuals.size()), &precise) && precise;
}

bool TrialResult::Inconclusive() const {
  bool precise = true;
  return ResidualsWithinNoise(*this, residuals.size(), &precise) && !precise;
}

double TrialResult::Cost() const {
  double cost = 0;
  for (double r : residuals) cost += r * r;
  return cost;
}

BatchTrialFunction Batched(TrialFunction trial) {
  return [trial = std::move(trial)](const std::vector<std::vector<double>>& units) {
    std::vector<TrialResult> out;
    out.reserve(units.size());
    for (const std::vector<double>& u : units) out.push_back(trial(u));
    return out;
  };
}

TrialResult EvaluateOne(const BatchTrialFunction& batch, const std::vector<double>& unit) {
  std::vector<TrialResult> out = batch({unit});
  if (out.size() != 1) return {};
  TrialResult t = std::move(out[0]);
  for (double r : t.residuals)
    if (!std::isfinite(r)) t.ok = false;
  return t;
}

bool OptimiserOptions::IsValid(std::string* error) const {
  namespace limits = objectives::limits;
  if (!limits::kMaxEvaluations.Contains(max_evaluations)) {
    if (error) *error = "max_evaluations: must be in " + limits::kMaxEvaluations.Text();
    return false;
  }
  if (!limits::kBatchSize.Contains(bracket_points)) {
    if (error) *error = "bracket_points: must be in " + limits::kBatchSize.Text();
    return false;
  }
  if (!limits::kUnitTolerance.Contains(unit_tolerance)) {
    if (error) *error = "unit_tolerance: must be in " + limits::kUnitTolerance.Text();
    return false;
  }
  if (!limits::kBatchSize.Contains(batch_size)) {
    if (error) *error = "batch_size: must be in " + limits::kBatchSize.Text();
    return false;
  }
  return true;
}

bool FindOptimiser(const std::string& name, Optimiser* out) {
  for (const Entry& e : kOptimisers)
    if (name == e.name) return *out = e.optimise, true;
  return false;
}

std::vector<std::string> OptimiserNames() {
  std::vector<std::string> names;
  for (const Entry& e : kOptimisers) names.push_back(e.name);
  return names;
}

}  // namespace demcal::calibrate
