// "differential_evolution": a seeded global search for multi-modal problems that proposes its
// candidates in batches: each generation of the population is one batch, evaluated side by side.
//
// Storn & Price's DE/rand/1/bin (J. Global Optim. 11, 341, 1997) on Σ residual² in the unit
// cube: the population (NP = max(batch_size, 5·n, 4) points) starts as a Latin hypercube drawn
// from `seed`, with the start candidate as its first member; each generation, member i gets a
// trial x_r1 + F·(x_r2 − x_r3) (r1, r2, r3 distinct and ≠ i, F = 0.7) crossed with x_i per
// coordinate with probability CR = 0.9 (one coordinate always from the mutant), a coordinate
// that leaves [0, 1] is put half-way between x_i and the bound it crossed; the trial replaces
// x_i if its cost is not larger. A failed sample costs +∞ (never kept). All draws come from one
// core::Rng seeded once, in a fixed order, so the same answers give the same batches (resume).
//
// Stops after the generation in which a candidate settled within noise (MatchRecord: with more
// targets than parameters a first match may lie 2–3σ from the estimate, so it searches on),
// when the population's extent is below unit_tolerance in every coordinate (converged), or at
// the budget (the last generation is cut to what the budget allows). The termination is
// within_noise whenever some candidate matched.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "calibrate/optimiser.h"
#include "core/math/random.h"

namespace demcal::calibrate {
namespace {

constexpr double kF = 0.7;
constexpr double kCr = 0.9;
constexpr int kPerParameter = 5;

struct Member {
  std::vector<double> u;
  double cost = std::numeric_limits<double>::infinity();
};

class Evolution {
 public:
  Evolution(const BatchTrialFunction& f, const OptimiserOptions& o, size_t parameters)
      : f_(f), options_(o), rng_(o.seed), record_(parameters) {}

  // Evaluates the points (cut to the budget); costs of failed samples are +∞. False if the
  // budget cut the batch.
  bool Evaluate(std::vector<Member>* members) {
    const int room = options_.max_evaluations - result_.evaluations;
    const bool cut = static_cast<int>(members->size()) > room;
    if (cut) members->resize(std::max(room, 0));
    if (members->empty()) return false;
    std::vector<std::vector<double>> points;
    for (const Member& m : *members) points.push_back(m.u);
    const std::vector<TrialResult> out = f_(points);
    ++result_.batches;
    for (size_t i = 0; i < members->size(); ++i) {
      ++result_.evaluations;
      TrialResult t = i < out.size() ? out[i] : TrialResult{};
      for (double r : t.residuals)
        if (!std::isfinite(r)) t.ok = false;
      if (!t.ok) continue;
      (*members)[i].cost = t.Cost();
      if (result_.best_unit.empty() || t.Cost() < result_.best_cost)
        result_.best_unit = (*members)[i].u, result_.best_cost = t.Cost();
      record_.Note(t);
    }
    return !cut;
  }

  OptimiserResult Run(const std::vector<double>& start);

 private:
  int Pick(int size, std::initializer_list<int> not_these) {
    for (;;) {
      const int r = static_cast<int>(rng_.Next() % static_cast<uint64_t>(size));
      if (std::find(not_these.begin(), not_these.end(), r) == not_these.end()) return r;
    }
  }
  // `cause`: what stopped the search. One that matched ends within_noise whatever stopped it.
  OptimiserResult Finish(Termination termination, const std::string& cause) {
    std::string message = cause + " without a match within noise";
    if (record_.settled()) {
      termination = Termination::kWithinNoise, message = "matched and settled within noise";
    } else if (record_.matched()) {
      termination = Termination::kWithinNoise;
      message = "matched within noise, then searched on: " + cause;
    }
    result_.termination = result_.best_unit.empty() ? Termination::kFailed : termination;
    std::ostringstream m;
    m << message << " (" << generations_ << " generations of " << size_ << ")";
    result_.message = result_.best_unit.empty() ? "no candidate gave a value" : m.str();
    return result_;
  }

  const BatchTrialFunction& f_;
  const OptimiserOptions& options_;
  core::Rng rng_;
  OptimiserResult result_;
  MatchRecord record_;
  int generations_ = 0, size_ = 0;
};

OptimiserResult Evolution::Run(const std::vector<double>& start) {
  const int n = static_cast<int>(start.size());
  size_ = std::max({options_.batch_size, kPerParameter * n, 4});
  // Latin hypercube: per coordinate, one point in each of size_ strata, strata shuffled.
  std::vector<Member> population(size_, Member{std::vector<double>(n)});
  for (int k = 0; k < n; ++k) {
    std::vector<int> strata(size_);
    std::iota(strata.begin(), strata.end(), 0);
    for (int i = size_ - 1; i > 0; --i) std::swap(strata[i], strata[rng_.Next() % (i + 1)]);
    for (int i = 0; i < size_; ++i) population[i].u[k] = (strata[i] + rng_.Uniform()) / size_;
  }
  population[0].u = start;
  for (double& v : population[0].u) v = std::clamp(v, 0.0, 1.0);
  const bool whole = Evaluate(&population);
  if (record_.settled()) return Finish(Termination::kWithinNoise, "settled");
  if (!whole) return Finish(Termination::kBudget, "budget used up in the first generation");
  for (;;) {
    double extent = 0;
    for (int k = 0; k < n; ++k) {
      double lo = 1, hi = 0;
      for (const Member& m : population) lo = std::min(lo, m.u[k]), hi = std::max(hi, m.u[k]);
      extent = std::max(extent, hi - lo);
    }
    if (extent < options_.unit_tolerance)
      return Finish(Termination::kConverged,
                    "population narrower than unit_tolerance");
    if (result_.evaluations >= options_.max_evaluations)
      return Finish(Termination::kBudget, "budget used up");
    std::vector<Member> trials(size_, Member{std::vector<double>(n)});
    for (int i = 0; i < size_; ++i) {
      const int r1 = Pick(size_, {i}), r2 = Pick(size_, {i, r1}), r3 = Pick(size_, {i, r1, r2});
      const int forced = static_cast<int>(rng_.Next() % static_cast<uint64_t>(n));
      for (int k = 0; k < n; ++k) {
        const double x = population[i].u[k];
        double v = population[r1].u[k] + kF * (population[r2].u[k] - population[r3].u[k]);
        if (v < 0) v = 0.5 * x;
        if (v > 1) v = 0.5 * (x + 1);
        trials[i].u[k] = (k == forced || rng_.Uniform() < kCr) ? v : x;
      }
    }
    const bool complete = Evaluate(&trials);
    ++generations_;
    for (size_t i = 0; i < trials.size(); ++i)
      if (trials[i].cost <= population[i].cost) population[i] = trials[i];
    if (record_.settled()) return Finish(Termination::kWithinNoise, "settled");
    if (!complete) return Finish(Termination::kBudget, "budget used up");
  }
}

}  // namespace

OptimiserResult DifferentialEvolution(const BatchTrialFunction& trial,
                                      const std::vector<double>& start_unit,
                                      const OptimiserOptions& options) {
  Evolution evolution(trial, options, start_unit.size());
  if (start_unit.empty()) {
    OptimiserResult r;
    r.message = "no parameters";
    return r;
  }
  return evolution.Run(start_unit);
}

}  // namespace demcal::calibrate
