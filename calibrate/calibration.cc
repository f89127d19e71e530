#include "calibrate/calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace demcal::calibrate {
namespace {

TrialResult Standardise(const Evaluation& e, const Measurement& m) {
  TrialResult t;
  t.ok = e.ok();
  if (!t.ok) return t;
  t.residuals = {(e.summary.mean - m.value) / m.uncertainty};
  t.noise = {e.summary.sem / m.uncertainty};
  return t;
}

// Slope of the observable against the single parameter: least-squares line through the best
// evaluation and its nearest (up to 3) neighbours with other parameter values.
void LocalSensitivity(const Measurement& m, CalibrationSummary* s) {
  if (s->best < 0) return;
  const Evaluation& best = s->history[s->best];
  if (best.parameters.size() != 1) {
    s->uncertainty_note = "not given: " + std::to_string(best.parameters.size()) +
                          " parameters against one measurement match along a valley, not at a "
                          "point; add a second measurement to fix them";
    return;
  }
  std::vector<const Evaluation*> near;
  for (const Evaluation& e : s->history)
    if (e.ok()) near.push_back(&e);
  std::sort(near.begin(), near.end(), [&](const Evaluation* a, const Evaluation* b) {
    return std::abs(a->parameters[0] - best.parameters[0]) < std::abs(b->parameters[0] - best.parameters[0]);
  });
  near.resize(std::min<size_t>(near.size(), 4));
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Evaluation* e : near) {
    sx += e->parameters[0], sy += e->summary.mean;
    sxx += e->parameters[0] * e->parameters[0], sxy += e->parameters[0] * e->summary.mean;
  }
  const double n = static_cast<double>(near.size()), det = n * sxx - sx * sx;
  if (near.size() < 2 || !(std::abs(det) > 0)) {
    s->uncertainty_note = "not given: fewer than two distinct candidates near the best";
    return;
  }
  const double slope = (n * sxy - sx * sy) / det;
  const double sigma = std::hypot(m.uncertainty, best.summary.sem);
  s->sensitivity = {slope};
  if (!(std::abs(slope) > 0)) {
    s->uncertainty = {0};
    s->uncertainty_note = "not identifiable: the observable does not change with the parameter here";
    return;
  }
  s->uncertainty = {sigma / std::abs(slope)};
  s->uncertainty_note = "sqrt(u_measured^2 + sem_simulated^2) / |slope|, slope fitted through the " +
                        std::to_string(near.size()) + " candidates nearest the best";
}

}  // namespace

CalibrationSummary Calibrate(ReplicatedEvaluator& evaluator, const ParameterSpace& space,
                             const Measurement& measurement, const CalibrationOptions& options,
                             const CalibrationProgress& progress) {
  CalibrationSummary s;
  Optimiser optimise = nullptr;
  std::string error;
  if (!FindOptimiser(options.optimiser, &optimise)) error = "optimiser: unknown '" + options.optimiser + "'";
  else if (!(measurement.uncertainty > 0)) error = "measurement.uncertainty: must be > 0";
  else options.optimiser_options.IsValid(&error);
  if (!error.empty()) {
    s.termination = "invalid";
    s.message = error;
    return s;
  }
  const auto start = std::chrono::steady_clock::now();
  auto trial = [&](const std::vector<double>& unit) {
    std::string journal_error;
    const Evaluation& e = s.history.emplace_back(evaluator.Evaluate(space.FromUnit(unit), &journal_error));
    if (s.journal_error.empty()) s.journal_error = journal_error;
    s.replicates_reused += e.reused;
    s.replicates_run += static_cast<int>(e.runs.size()) - e.reused;
    const TrialResult t = Standardise(e, measurement);
    if (progress)
      progress(e, t, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return t;
  };
  const OptimiserResult r = optimise(trial, space.ToUnit(space.Start()), options.optimiser_options);
  s.termination = r.termination;
  s.message = r.message;
  for (const Evaluation& e : s.history) {  // the best candidate: the smallest |residual|
    const TrialResult t = Standardise(e, measurement);
    if (t.ok && (s.best < 0 || std::abs(t.residuals[0]) < std::abs(s.best_residual)))
      s.best = e.index, s.best_residual = t.residuals[0];
  }
  LocalSensitivity(measurement, &s);
  return s;
}

std::string CalibrationSummary::BriefReport(const ParameterSpace& space, const Measurement& m) const {
  std::ostringstream out;
  out.precision(4);
  out << "calibration: " << termination << " (" << message << "), " << history.size()
      << " candidates, " << replicates_run << " replicate runs (+" << replicates_reused
      << " from the journal)\n";
  if (best < 0) return out.str();
  const Evaluation& e = history[best];
  out << "best: " << space.Describe(e.parameters) << " -> " << m.observable << " = " << e.summary.mean
      << " +- " << e.summary.sem << " (measured " << m.value << " +- " << m.uncertainty << ")\n";
  for (size_t k = 0; k < uncertainty.size(); ++k)
    out << "uncertainty: " << space.parameters[k].name << " +- " << uncertainty[k] << "\n";
  if (!uncertainty_note.empty()) out << "uncertainty: " << uncertainty_note << "\n";
  return out.str();
}

}  // namespace demcal::calibrate
