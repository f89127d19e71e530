#pragma once
// Optimisers: search the unit cube of a ParameterSpace for the candidate whose simulated
// observables match the measured ones. They see a black box that maps unit-cube points to
// standardised residuals (simulated − measured) / measurement uncertainty, with the simulation's
// own noise (its standard error, in the same units) alongside, or reports a failed sample.
// A candidate whose every |residual| is within sqrt(1 + noise²) matches "within noise", and no
// optimiser refines beyond that: two numbers closer than their noise are not told apart. A match
// also needs a simulation at least as precise as the measurement (every noise ≤ 1): a candidate
// whose replicates scatter more than the measurement's uncertainty would be "within noise" of
// almost anything, so it confirms nothing (Inconclusive; the driver re-runs such a candidate
// with more replicates, calibration.h).
//
// The black box takes a *batch* of points (BatchTrialFunction): the caller evaluates them
// concurrently (replicates and candidates of a batch side by side). Sequential optimisers ask
// for one point at a time; the batch ones (ceres' finite differences, differential_evolution's
// generations) ask for several. Every optimiser is deterministic: the same inputs and the same
// answers give the same sequence of batches, so a rerun after a kill asks for the same
// candidates and finds them in the journal.
//
// An optimiser is one file defining a function of type Optimiser, registered by name in
// optimiser_registry.cc.
//
//   Optimiser optimise;
//   if (!FindOptimiser("bracket", &optimise)) ...;
//   OptimiserResult r = optimise(batch_trial, space.ToUnit(space.Start()), {.max_evaluations =
//   15});
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "calibrate/termination.h"

namespace demcal::calibrate {

// The largest simulation noise (sem / measurement uncertainty) of a match: the simulation may
// not be the less precise of the two numbers compared.
inline constexpr double kMatchNoise = 1.0;
// P(|z| ≤ 1) for a standard normal z: the confidence of "within noise" (1σ), in any number of
// targets (TrialResult::WithinNoise).
inline constexpr double kWithinNoiseProbability = 0.6826894921370859;

// One candidate's answer. Thread-safety: a plain value.
struct TrialResult {
  bool ok = false;                // false: the simulation gave no value here (infeasible)
  std::vector<double> residuals;  // (simulated − measured) / measurement uncertainty
  std::vector<double> noise;      // simulation standard error / measurement uncertainty
  // The m residuals agree within noise jointly — Σ residual² / (1 + noise²) no larger than the
  // χ²_m quantile at 68.27 %, the probability of |z| ≤ 1 — and every noise ≤ kMatchNoise: a
  // match. For one target this is |residual| ≤ sqrt(1 + noise²), the 1σ rule; for m targets
  // it keeps the same confidence (asking each of m targets to lie within its own 1σ would
  // reject the true parameters with probability 1 − 0.68^m: 90 % for six targets).
  bool WithinNoise() const;
  // Where a search for n parameters may stop: the same sum no larger than the χ²_min(m, n)
  // quantile at 68.27 % (and every noise ≤ kMatchNoise). The parameters' joint 1σ region is
  // χ²(θ) − χ²_min ≤ that quantile and χ²_min ≥ 0, so a settled candidate lies inside it. With
  // more targets than parameters a mere match (χ²_m) can lie 2–3σ from the least-squares
  // estimate (seen on the Γ-per-coating twin: 6 targets, 3 parameters); for m ≤ n the two agree.
  bool Settled(size_t parameters) const;
  // Within noise jointly, but some noise > kMatchNoise: more replicates would tell whether this
  // is a match.
  bool Inconclusive() const;
  double Cost() const;  // Σ residual²
};

// The stop rule every optimiser follows, kept in one place so that none stops at a mere first
// match: a search for n parameters notes each candidate's answer and may stop at the first one
// that settled (TrialResult::Settled); its termination is "within_noise" if any candidate
// matched (TrialResult::WithinNoise), settled or not.
class MatchRecord {
 public:
  explicit MatchRecord(size_t parameters) : parameters_(parameters) {}
  // True when the search may stop at this candidate.
  bool Note(const TrialResult& t) {
    matched_ = matched_ || t.WithinNoise();
    const bool settled = t.Settled(parameters_);
    settled_ = settled_ || settled;
    return settled;
  }
  bool matched() const { return matched_; }
  bool settled() const { return settled_; }

 private:
  size_t parameters_;
  bool matched_ = false;
  bool settled_ = false;
};

// Unit-cube points in, one TrialResult per point out (same order). A NaN residual must be
// reported as ok = false by the caller; optimisers also treat a non-finite residual so.
using BatchTrialFunction =
    std::function<std::vector<TrialResult>(const std::vector<std::vector<double>>& units)>;
// One-point convenience for tests and sequential callers.
using TrialFunction = std::function<TrialResult(const std::vector<double>& unit)>;
BatchTrialFunction Batched(TrialFunction trial);
// Asks `batch` for one point; a malformed answer (wrong count, non-finite residual) is a
// failed sample.
TrialResult EvaluateOne(const BatchTrialFunction& batch, const std::vector<double>& unit);

// Options shared by every optimiser. Defaults suit a few-parameter DEM calibration. Allowed
// ranges: objectives/common/input_limits.h (kMaxEvaluations, kUnitTolerance, kBatchSize).
struct OptimiserOptions {
  int max_evaluations = 20;       // candidates the optimiser may ask for (journal hits included)
  double unit_tolerance = 0.002;  // stop when the search interval / step is this small (unit cube)
  int batch_size = 4;             // candidates per batch of the batch optimisers; set it >= the
                                  // cores that evaluate them
  // Candidates per refining round of `bracket` (k-section; 1: regula falsi, one at a time). Not
  // batch_size: its default (4) suits the batch optimisers, and a bracket study that names no
  // k must keep its one-candidate search, which its journal records.
  int bracket_points = 1;
  uint64_t seed = 1;              // for the optimisers that draw (differential_evolution)
  bool IsValid(std::string* error) const;
};

struct OptimiserResult {
  Termination termination = Termination::kFailed;  // never kInvalid (termination.h)
  std::string message = "not run";
  std::vector<double> best_unit;  // the best candidate evaluated
  double best_cost = 0;
  int evaluations = 0;
  int batches = 0;
  // Filled by optimisers that estimate it (ceres: ceres::Covariance at the best candidate):
  // covariance of the unit-cube parameters, n×n row-major, empty when not computed, with why.
  std::vector<double> covariance_unit;
  std::string covariance_note;
};

using Optimiser = OptimiserResult (*)(const BatchTrialFunction& trial,
                                      const std::vector<double>& start_unit,
                                      const OptimiserOptions& options);

bool FindOptimiser(const std::string& name, Optimiser* out);
std::vector<std::string> OptimiserNames();

// The optimisers (each in its own file).
OptimiserResult BracketOptimise(const BatchTrialFunction&, const std::vector<double>&,
                                const OptimiserOptions&);
OptimiserResult NloptBobyqa(const BatchTrialFunction&, const std::vector<double>&,
                            const OptimiserOptions&);
OptimiserResult NloptCobyla(const BatchTrialFunction&, const std::vector<double>&,
                            const OptimiserOptions&);
OptimiserResult NloptNelderMead(const BatchTrialFunction&, const std::vector<double>&,
                                const OptimiserOptions&);
OptimiserResult CeresOptimise(const BatchTrialFunction&, const std::vector<double>&,
                              const OptimiserOptions&);
OptimiserResult DifferentialEvolution(const BatchTrialFunction&, const std::vector<double>&,
                                      const OptimiserOptions&);

}  // namespace demcal::calibrate
