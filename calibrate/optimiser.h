#pragma once
// Optimisers: search the unit cube of a ParameterSpace for the candidate whose simulated
// observables match the measured ones. They see a black box that maps a unit-cube point to
// standardised residuals (simulated − measured) / measurement uncertainty, with the simulation's
// own noise (its standard error, in the same units) alongside, or reports a failed sample.
// A candidate whose every |residual| is within sqrt(1 + noise²) matches "within noise", and no
// optimiser refines beyond that: two numbers closer than their noise are not told apart.
//
// An optimiser is one file defining a function of type Optimiser, registered by name in
// optimiser_registry.cc.
//
//   Optimiser optimise;
//   if (!FindOptimiser("bracket", &optimise)) ...;
//   OptimiserResult r = optimise(trial, space.ToUnit(space.Start()), {.max_evaluations = 15});
#include <functional>
#include <string>
#include <vector>

namespace demcal::calibrate {

struct TrialResult {
  bool ok = false;                // false: the simulation gave no value here (infeasible)
  std::vector<double> residuals;  // (simulated − measured) / measurement uncertainty
  std::vector<double> noise;      // simulation standard error / measurement uncertainty
  // Every residual within sqrt(1 + noise²).
  bool WithinNoise() const;
  double Cost() const;  // Σ residual²
};

using TrialFunction = std::function<TrialResult(const std::vector<double>& unit)>;

struct OptimiserOptions {
  int max_evaluations = 20;     // candidates the optimiser may ask for (journal hits included)
  double unit_tolerance = 0.002;  // stop when the search interval / step is this small (unit cube)
  bool IsValid(std::string* error) const;
};

struct OptimiserResult {
  // "within_noise" (a match), "converged" (tolerance reached, no match within noise),
  // "out_of_range" (the measurement lies outside what the bounds reach), "budget", "failed".
  std::string termination = "failed";
  std::string message = "not run";
  std::vector<double> best_unit;  // the best candidate evaluated
  double best_cost = 0;
  int evaluations = 0;
};

using Optimiser = OptimiserResult (*)(const TrialFunction& trial, const std::vector<double>& start_unit,
                                      const OptimiserOptions& options);

bool FindOptimiser(const std::string& name, Optimiser* out);
std::vector<std::string> OptimiserNames();

// The optimisers (each in its own file).
OptimiserResult BracketOptimise(const TrialFunction&, const std::vector<double>&, const OptimiserOptions&);
OptimiserResult NloptBobyqa(const TrialFunction&, const std::vector<double>&, const OptimiserOptions&);
OptimiserResult NloptCobyla(const TrialFunction&, const std::vector<double>&, const OptimiserOptions&);
OptimiserResult NloptNelderMead(const TrialFunction&, const std::vector<double>&, const OptimiserOptions&);

}  // namespace demcal::calibrate
