// NLopt's derivative-free local optimisers on the unit cube, minimising Σ residual² (the
// chi-square against the measurement uncertainties). A failed sample costs kFailedCost, so the
// optimiser steps away from it instead of stopping. The search stops at the first candidate
// that settled within noise (MatchRecord; nlopt::forced_stop thrown from the objective is
// NLopt's way to end early), at the tolerance on the step, or at the budget.
#include <nlopt.hpp>

#include <algorithm>
#include <exception>

#include "calibrate/optimiser.h"

namespace demcal::calibrate {
namespace {

constexpr double kFailedCost = 1e6;

OptimiserResult Run(nlopt::algorithm algorithm, const BatchTrialFunction& trial,
                    const std::vector<double>& start_unit, const OptimiserOptions& options) {
  OptimiserResult result;
  const unsigned n = static_cast<unsigned>(start_unit.size());
  MatchRecord record(n);
  nlopt::opt opt(algorithm, n);
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_maxeval(options.max_evaluations);
  opt.set_xtol_abs(options.unit_tolerance);
  opt.set_initial_step(std::vector<double>(n, 0.25));
  auto objective = [&](const std::vector<double>& u) {
    const TrialResult t = EvaluateOne(trial, u);
    ++result.evaluations;
    ++result.batches;
    const double cost = t.ok ? t.Cost() : kFailedCost;
    if (t.ok && (result.best_unit.empty() || cost < result.best_cost)) {
      result.best_unit = u;
      result.best_cost = cost;
    }
    if (record.Note(t)) throw nlopt::forced_stop();  // inside the parameters' 1σ region
    return cost;
  };
  using Objective = decltype(objective);
  opt.set_min_objective(
      [](const std::vector<double>& u, std::vector<double>&, void* data) {
        return (*static_cast<Objective*>(data))(u);
      },
      &objective);
  std::vector<double> x(start_unit);
  for (double& v : x) v = std::clamp(v, 0.0, 1.0);
  double cost = 0;
  try {
    const nlopt::result r = opt.optimize(x, cost);
    const bool budget = r == nlopt::MAXEVAL_REACHED;
    const bool matched = record.matched();
    result.termination = matched  ? Termination::kWithinNoise
                         : budget ? Termination::kBudget
                                  : Termination::kConverged;
    result.message = matched  ? std::string("matched within noise, then searched on to the ") +
                                    (budget ? "budget" : "unit tolerance")
                     : budget ? "budget used up before a match within noise"
                              : "step below unit_tolerance without a match within noise";
  } catch (const nlopt::forced_stop&) {
    result.termination = record.matched() ? Termination::kWithinNoise : Termination::kFailed;
    result.message = record.matched() ? "matched and settled within noise" : "NLopt stopped";
  } catch (const std::exception& e) {
    result.termination = Termination::kFailed;
    result.message = std::string("NLopt: ") + e.what();
  }
  if (result.best_unit.empty() && result.termination != Termination::kFailed) {
    result.termination = Termination::kFailed;
    result.message = "no candidate gave a value";
  }
  return result;
}

}  // namespace

OptimiserResult NloptBobyqa(const BatchTrialFunction& t, const std::vector<double>& s, const OptimiserOptions& o) {
  return Run(nlopt::LN_BOBYQA, t, s, o);
}
OptimiserResult NloptCobyla(const BatchTrialFunction& t, const std::vector<double>& s, const OptimiserOptions& o) {
  return Run(nlopt::LN_COBYLA, t, s, o);
}
OptimiserResult NloptNelderMead(const BatchTrialFunction& t, const std::vector<double>& s, const OptimiserOptions& o) {
  return Run(nlopt::LN_NELDERMEAD, t, s, o);
}

}  // namespace demcal::calibrate
