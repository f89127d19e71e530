#include "calibrate/calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "calibrate/jacobian_svd.h"
#include "calibrate/parameter_covariance.h"
#include "calibrate/sensitivity_refinement.h"

namespace demcal::calibrate {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Standardised residuals; a missing or non-finite value is an infeasible sample.
TrialResult Standardise(const CandidateResult& c, const std::vector<Target>& targets) {
  TrialResult t;
  if (!c.ok() || c.targets.size() != targets.size()) return t;
  for (size_t k = 0; k < targets.size(); ++k) {
    const double r = (c.targets[k].mean - targets[k].value) / targets[k].uncertainty;
    const double noise = c.targets[k].sem / targets[k].uncertainty;
    if (!std::isfinite(r) || !std::isfinite(noise)) return TrialResult{};
    t.residuals.push_back(r);
    t.noise.push_back(noise);
  }
  t.ok = true;
  return t;
}

// The replicates a candidate came with (before Sharpen or Deepen added any).
int BaseReplicates(const Candidate& c) {
  int most = 0;
  for (const TargetValue& v : c.result.targets) most = std::max(most, v.replicates);
  return most - c.replicates_added;
}

// Re-runs candidate c with n replicates per group (those already run are reused); false if the
// evaluator cannot.
bool Rerun(CandidateEvaluator& evaluator, const std::vector<Target>& targets, int n, Candidate* c,
           CalibrationSummary* s) {
  const int base = BaseReplicates(*c);
  std::optional<CandidateResult> more = evaluator.AddReplicates(c->parameters, n);
  if (!more) return false;
  c->result = std::move(*more);
  c->trial = Standardise(c->result, targets);
  c->replicates_added = n - base;
  s->replicates_run += c->result.replicates_run;
  s->replicates_reused += c->result.replicates_reused;  // the added replicates a journal held
  return true;
}

// Re-runs an inconclusive candidate with more replicates until it is conclusive or has
// `factor` times the replicates it came with (CalibrationOptions::max_replicate_factor).
void Sharpen(CandidateEvaluator& evaluator, const std::vector<Target>& targets, int factor,
             Candidate* c, CalibrationSummary* s) {
  const int cap = factor * BaseReplicates(*c);
  for (int n = BaseReplicates(*c); c->trial.Inconclusive() && n < cap;) {
    double worst = 0;
    for (double noise : c->trial.noise) worst = std::max(worst, noise / kMatchNoise);
    n = std::min(cap, std::max(n + 1, static_cast<int>(std::ceil(n * worst * worst))));
    if (!Rerun(evaluator, targets, n, c, s)) return;
  }
}

// Brings a candidate to `factor` times the replicates it came with (sensitivity refinement:
// the noise of the estimated sensitivities falls as 1/√n).
void Deepen(CandidateEvaluator& evaluator, const std::vector<Target>& targets, int factor,
            Candidate* c, CalibrationSummary* s) {
  if (!c->trial.ok) return;
  const int cap = factor * BaseReplicates(*c);
  int most = 0;
  for (const TargetValue& v : c->result.targets) most = std::max(most, v.replicates);
  if (most < cap) Rerun(evaluator, targets, cap, c, s);
}

std::string Validate(const ParameterSpace& space, const std::vector<Target>& targets,
                     const CalibrationOptions& options, Optimiser* optimise) {
  std::string error;
  if (!FindOptimiser(options.optimiser, optimise))
    return "optimiser: unknown '" + options.optimiser + "'";
  if (space.Size() == 0) return "parameters: at least one parameter is needed";
  if (targets.empty()) return "targets: at least one target is needed";
  std::set<std::string> names;
  for (size_t k = 0; k < targets.size(); ++k) {
    const std::string at = "targets[" + std::to_string(k) + "]";
    if (!(targets[k].uncertainty > 0 && std::isfinite(targets[k].uncertainty)))
      return at + ".uncertainty: must be finite and > 0";
    if (!std::isfinite(targets[k].value)) return at + ".value: must be finite";
    if (!names.insert(targets[k].name).second)
      return at + ".name: '" + targets[k].name + "' is used twice";
  }
  if (!options.optimiser_options.IsValid(&error)) return error;
  if (options.max_replicate_factor < 1 || options.max_replicate_factor > 100)
    return "max_replicate_factor: must be in [1, 100]";
  if (options.sensitivity_rounds < 0 || options.sensitivity_rounds > 10)
    return "sensitivity_rounds: must be in [0, 10]";
  if (!options.response_surface.IsValid(&error)) return "response_surface." + error;
  return "";
}

// J at the best (response surface, rows weighted by 1/sqrt(1 + noise²)), σ and correlations,
// identifiability. Replaces what an earlier call wrote (refinement analyses again).
void Analyse(const ParameterSpace& space, const std::vector<Target>& targets,
             const CalibrationOptions& options, const OptimiserResult& r, CalibrationSummary* s) {
  s->residuals.clear(), s->estimates.clear(), s->covariance_note.clear();
  s->jacobian.resize(0, 0), s->jacobian_sigma.resize(0, 0);
  s->covariance.resize(0, 0), s->correlation.resize(0, 0);
  s->identifiability = {};
  const Candidate& best = s->candidates[s->best];
  const size_t n = space.Size();
  std::vector<std::string> names;
  for (const Parameter& p : space.parameters) names.push_back(p.name);
  const std::vector<double> scale = SiPerUnit(space, best.unit);
  for (size_t k = 0; k < targets.size(); ++k) {
    const TargetValue& v = best.result.targets[k];
    s->residuals.push_back({targets[k].name, targets[k].observable, targets[k].value,
                            targets[k].uncertainty, v.mean, v.sem, best.trial.residuals[k],
                            std::abs(best.trial.residuals[k]) <=
                                std::sqrt(1 + best.trial.noise[k] * best.trial.noise[k])});
  }
  for (size_t k = 0; k < n; ++k)
    s->estimates.push_back({names[k], best.parameters[k], kInf, false});
  std::vector<Sample> samples;
  for (const Candidate& c : s->candidates) samples.push_back({c.unit, c.trial});
  const ResponseSurface surface = FitResponseSurface(samples, best.unit, options.response_surface);
  s->jacobian_note = surface.message;
  if (!surface.ok) {
    s->covariance_note = "not given: " + surface.message;
    return;
  }
  s->jacobian = surface.jacobian;
  s->jacobian_sigma = surface.jacobian_sigma;
  for (size_t i = 0; i < targets.size(); ++i) {
    const double w = 1 / std::sqrt(1 + best.trial.noise[i] * best.trial.noise[i]);
    s->jacobian.row(i) *= w;
    s->jacobian_sigma.row(i) *= w;
  }
  // Sensitivities estimated from noisy runs resolve only the directions above their own noise.
  const double floor = JacobianNoiseFloor(s->jacobian_sigma);
  s->identifiability = AnalyseIdentifiability(s->jacobian, names, scale, floor);
  ParameterCovariance c = CovarianceFromJacobian(s->jacobian, scale, floor);
  // Ceres' covariance comes from its own stencil: not once refinement points sharpened J.
  const bool ceres_cov = r.covariance_unit.size() == n * n && c.rank == static_cast<int>(n) &&
                         r.best_unit == best.unit && s->refinement_points == 0;
  if (ceres_cov) {
    c = CovarianceFromUnit(Eigen::Map<const Eigen::MatrixXd>(r.covariance_unit.data(), n, n),
                           scale);
    c.note = r.covariance_note;
  } else {
    c.note += " (" + surface.message + ")";
  }
  if (s->refinement_points > 0)
    c.note += "; " + std::to_string(s->refinement_points) +
              " refinement candidates around the best sharpened the sensitivities";
  s->covariance_note = c.note;
  s->covariance = c.covariance;
  s->correlation = c.correlation;
  for (size_t k = 0; k < n; ++k) {
    s->estimates[k].sigma = c.sigma[k];
    s->estimates[k].identifiable = c.identifiable[k];
  }
}

// Sensitivity refinement (sensitivity_refinement.h), after a first Analyse: stencil rounds around
// the best, each analysed again, while some σ is +∞, the targets are at least as many as the
// parameters and the budget allows.
template <class Batch>
void RefineSensitivities(Batch& batch, CandidateEvaluator& evaluator, const ParameterSpace& space,
                         const std::vector<Target>& targets, const CalibrationOptions& options,
                         const OptimiserResult& r, CalibrationSummary* s) {
  if (targets.size() < space.Size()) return;  // a valley no stencil can lift
  auto any_infinite = [&] {
    return std::any_of(s->estimates.begin(), s->estimates.end(),
                       [](const ParameterEstimate& e) { return !std::isfinite(e.sigma); });
  };
  for (int round = 0; round < options.sensitivity_rounds && any_infinite(); ++round) {
    const Candidate& best = s->candidates[s->best];
    double noise_max = 0;
    for (double noise : best.trial.noise) noise_max = std::max(noise_max, noise);
    const std::vector<std::vector<double>> units = RefinementStencil(best.unit, noise_max, round);
    if (units.empty() || s->candidates.size() + units.size() >
                             static_cast<size_t>(options.optimiser_options.max_evaluations))
      return;
    const size_t first_new = s->candidates.size();
    batch(units);  // appends to s->candidates: `best` is not used after this
    s->refinement_points += static_cast<int>(units.size());
    // The stencil at the most replicates allowed: a sensitivity is a difference of noisy means,
    // and it was their noise that left σ at +∞. (The best keeps its replicates: its match, and
    // so the termination, stay as the optimiser found them.)
    for (size_t k = first_new; k < s->candidates.size(); ++k)
      Deepen(evaluator, targets, options.max_replicate_factor, &s->candidates[k], s);
    Analyse(space, targets, options, r, s);
  }
}

// The local crossing of a one-parameter, one-target search that matched no candidate, with its
// value and σ in SI (σ through the unit-to-SI slope at the crossing).
void FitCrossing(const ParameterSpace& space, CalibrationSummary* s) {
  std::vector<Sample> samples;
  for (const Candidate& c : s->candidates) samples.push_back({c.unit, c.trial});
  s->local_crossing = FitLocalCrossing(samples);
  if (!s->local_crossing.fitted) return;
  const std::vector<double> unit{s->local_crossing.unit};
  s->local_crossing_value = space.FromUnit(unit)[0];
  s->local_crossing_sigma = SiPerUnit(space, unit)[0] * s->local_crossing.unit_sigma;
}

}  // namespace

CalibrationSummary Calibrate(CandidateEvaluator& evaluator, const ParameterSpace& space,
                             const std::vector<Target>& targets, const CalibrationOptions& options,
                             const CandidateProgress& progress) {
  CalibrationSummary s;
  Optimiser optimise = nullptr;
  const std::string error = Validate(space, targets, options, &optimise);
  if (!error.empty()) {
    s.termination = Termination::kInvalid;
    s.message = error;
    return s;
  }
  const auto start = std::chrono::steady_clock::now();
  auto batch = [&](const std::vector<std::vector<double>>& units) {
    std::vector<std::vector<double>> si;
    for (const auto& u : units) si.push_back(space.FromUnit(u));
    std::vector<CandidateResult> results = evaluator.EvaluateBatch(si);
    ++s.batches;
    std::vector<TrialResult> trials;
    for (size_t i = 0; i < units.size(); ++i) {
      Candidate& c = s.candidates.emplace_back();
      c.index = static_cast<int>(s.candidates.size()) - 1;
      c.parameters = si[i];
      c.unit = units[i];
      if (i < results.size())
        c.result = std::move(results[i]);
      else
        c.result.status = "no_result";  // the evaluator answered fewer candidates
      c.trial = Standardise(c.result, targets);
      s.replicates_run += c.result.replicates_run;
      s.replicates_reused += c.result.replicates_reused;
      Sharpen(evaluator, targets, options.max_replicate_factor, &c, &s);
      if (s.journal_error.empty()) s.journal_error = c.result.journal_error;
      trials.push_back(c.trial);
      if (progress)
        progress(c,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return trials;
  };
  const OptimiserResult r = optimise(batch, space.ToUnit(space.Start()), options.optimiser_options);
  s.termination = r.termination;
  s.message = r.message;
  // The best: among the candidates within noise (if any, as the termination then says), the
  // smallest Σ residual², first on ties. A lower cost outside noise does not beat a match: its
  // residuals are not told apart from the match's by the data, and its own are not all within.
  bool any_within = false;
  for (const Candidate& c : s.candidates) any_within = any_within || (c.trial.ok && c.trial.WithinNoise());
  for (const Candidate& c : s.candidates)
    if (c.trial.ok && (!any_within || c.trial.WithinNoise()) &&
        (s.best < 0 || c.trial.Cost() < s.candidates[s.best].trial.Cost()))
      s.best = c.index;
  if (s.best >= 0) {
    Analyse(space, targets, options, r, &s);
    RefineSensitivities(batch, evaluator, space, targets, options, r, &s);
  }
  if (!any_within && space.Size() == 1 && targets.size() == 1) FitCrossing(space, &s);
  return s;
}

}  // namespace demcal::calibrate
