#include "diagnose/loop/refit_work.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibrate/sensitivity_refinement.h"

namespace demcal::diagnose::refits {

Eigen::VectorXd ToVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
}

Frame MakeFrame(const std::vector<Observation>& observations, const FitState& fit,
                const DiagnoseOptions& o) {
  Frame f{&observations};
  const std::vector<Observation> at =
      WithPrediction(observations, fit.prediction, o.discrepancy_floor);
  f.sigma = Sigmas(at);
  f.q = ScatterPerSigma(at);
  f.r0 = StandardisedResiduals(observations, fit.prediction.mean, f.sigma);
  f.J = f.sigma.cwiseInverse().asDiagonal() * fit.jacobian;
  const std::vector<double> c = fit.Coordinates();
  for (size_t j = 0; j < c.size(); ++j) {
    f.delta_lower.push_back(fit.lower[j] - c[j]);
    f.delta_upper.push_back(fit.upper[j] - c[j]);
  }
  f.fitted = fit.Fitted();
  f.chi2_base = f.r0.squaredNorm();
  f.significance = o.significance;
  return f;
}

LinearRefitResult Refit(const Frame& f, const EffectParameter& p,
                        const Eigen::VectorXd& signature) {
  const Eigen::MatrixXd S = f.sigma.cwiseInverse().cwiseProduct(signature);
  return LinearRefit(f.r0, f.J, S, {p.lower}, {p.upper}, f.delta_lower, f.delta_upper);
}

namespace {

// The simulation-noise sd of a simulated point's χ² at residuals r (evidence.h,
// CorrelatedChi2NoiseSd), with the discrepancy floor phi in the weights; 0 without a sem per row.
double PointChi2NoiseSd(const Frame& f, const Prediction& p, const Eigen::VectorXd& r, double phi) {
  if (p.sem.size() != static_cast<size_t>(f.n())) return 0;
  const Eigen::VectorXd u = ToVector(p.sem).cwiseQuotient(f.sigma);
  return CorrelatedChi2NoiseSd(r, u, f.q, phi, ErrorCorrelation(p.source, p.correlation, u.size()));
}

}  // namespace

void Fill(const Frame& f, const Work& w, const std::vector<CandidateEffect>& candidates,
          const Eigen::VectorXd& r, RankingEntry* e) {
  const int k = static_cast<int>(candidates[w.candidate].parameters.size());
  e->candidate = w.candidate;
  e->key = candidates[w.candidate].key;
  e->mechanism = candidates[w.candidate].mechanism;
  e->chi2_linear = w.refit.chi2;
  e->linear = EvidenceWithFloor(f.r0, w.refit.residuals, f.q, k, f.fitted, f.per_candidate);
  e->simulated = w.simulated;
  e->chi2 = w.simulated ? w.best_chi2 : w.refit.chi2;
  e->evidence = EvidenceWithFloor(f.r0, r, f.q, k, f.fitted, f.per_candidate);
  // The simulated refit's χ² moves with its points' simulation noise (evidence.h, ToldApart):
  // the ranking does not tell two candidates apart by less than that.
  if (w.simulated && w.best_prediction.sem.size() == static_cast<size_t>(f.n()))
    e->evidence.chi2_noise_sd = PointChi2NoiseSd(f, w.best_prediction, r, e->evidence.floor);
  e->chi2_per_dof = e->chi2 / std::max(1, f.n() - f.fitted - k);
  e->control = candidates[w.candidate].control;
  if (w.simulated) e->base_unit = w.best_point.base_unit;
  e->signature_match = SignatureMatch(f.r0, f.J, f.sigma.cwiseInverse().cwiseProduct(w.signature));
  if (w.best_point.effects.empty())
    e->values = {w.refit.t(0)};
  else
    e->values = w.best_point.effects.back().values;
}

void KeepSignatureRun(const Frame& f, const ModelPoint& point, const Prediction& run, Work* w) {
  w->signature_point = point;
  w->signature_prediction = run;
  if (!run.ok) return;
  const double chi2 = StandardisedResiduals(*f.observations, run.mean, f.sigma).squaredNorm();
  if (chi2 < w->probe_chi2) w->probe_chi2 = chi2, w->probe_point = point, w->probe_prediction = run;
}

namespace {

std::string ValueText(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

// A note once: the second Gauss–Newton call repeats a point that had no value (the secant
// needs a value to move it), which the journal answers without a run.
void AddNote(Work* w, const std::string& note) {
  if (w->retake_note.find(note) != std::string::npos) return;
  w->retake_note += (w->retake_note.empty() ? "" : "; ") + note;
}

}  // namespace

void SimulateRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                    const std::vector<CandidateEffect>& candidates, std::vector<Work*>& work) {
  std::vector<ModelPoint> points;
  std::vector<double> scale(work.size(), 1.0);  // the share of the Gauss–Newton step taken
  for (Work* w : work) {
    const ActiveEffect added{w->candidate, {w->refit.t(0)}};
    points.push_back(fit.Step(w->refit.delta, &added));
  }
  std::vector<Prediction> got = model.Evaluate(points);
  std::vector<size_t> at;  // points without a value, retaken at half the step (header)
  std::vector<ModelPoint> halves;
  for (size_t i = 0; i < work.size(); ++i) {
    if (got[i].ok) continue;
    const ActiveEffect added{work[i]->candidate, {0.5 * work[i]->refit.t(0)}};
    halves.push_back(fit.Step(0.5 * work[i]->refit.delta, &added));
    at.push_back(i);
  }
  const std::vector<Prediction> retaken = halves.empty() ? got : model.Evaluate(halves);
  for (size_t k = 0; k < at.size(); ++k) {
    Work& w = *work[at[k]];
    const std::string name = candidates[w.candidate].parameters[0].name;
    AddNote(&w, "refit point " + name + " = " + ValueText(w.refit.t(0)) + " had no value (" +
                    got[at[k]].status +
                    "); at half the step: " + (retaken[k].ok ? "ok" : retaken[k].status));
    if (!retaken[k].ok) continue;
    points[at[k]] = halves[k], got[at[k]] = retaken[k], scale[at[k]] = 0.5;
  }
  for (size_t i = 0; i < work.size(); ++i) {
    Work& w = *work[i];
    if (!got[i].ok) {
      if (!w.simulated && w.signature_prediction.ok) {
        w.best_chi2 = StandardisedResiduals(*f.observations, w.signature_prediction.mean, f.sigma)
                          .squaredNorm();
        w.best_point = w.signature_point, w.best_prediction = w.signature_prediction;
        w.simulated = true;
        AddNote(&w, "refitted from its signature run");
      }
      continue;
    }
    const double chi2 = StandardisedResiduals(*f.observations, got[i].mean, f.sigma).squaredNorm();
    if (!w.simulated || chi2 < w.best_chi2) {
      w.best_chi2 = chi2, w.best_point = points[i], w.best_prediction = got[i], w.simulated = true;
    }
    const double t = scale[i] * w.refit.t(0);
    if (t != 0) {
      const Eigen::VectorXd moved = ToVector(got[i].mean) - ToVector(fit.prediction.mean) -
                                    fit.jacobian * (scale[i] * w.refit.delta);
      w.signature = moved / t;
    }
    w.refit = Refit(f, candidates[w.candidate].parameters[0], w.signature);
  }
}

void Record(const Frame& f, const Work& w, const std::vector<CandidateEffect>& candidates, int i,
            DiagnosisStep* step) {
  RankingEntry& e = step->entries[i];
  const Eigen::VectorXd r =
      w.simulated ? StandardisedResiduals(*f.observations, w.best_prediction.mean, f.sigma)
                  : w.refit.residuals;
  Fill(f, w, candidates, r, &e);
  if (!w.probe_ok)
    e.note = "signature run failed: " + w.probe_status;
  else if (e.signature_match == 0)
    e.note = "redundant with the fitted parameters";
  if (!w.retake_note.empty()) e.note += (e.note.empty() ? "" : "; ") + w.retake_note;
  step->refit_residuals[i].assign(r.data(), r.data() + r.size());
}

namespace {

// A finite-difference probe without a value (a jammed funnel, a failed run) is retaken one step
// on the other side of the point when that side is inside the coordinate's range, and the
// derivative is then the one-sided backward difference from it: the same first-order accuracy
// as the forward one, where keeping the old sensitivity would step on a derivative taken
// elsewhere. probes, steps and probed are updated in place; index j < p is base coordinate j
// (bounds fit.lower/upper), j == p the candidate's effect parameter (its own range).
void RetakeOnOtherSide(ForwardModel& model, const FitState& fit,
                       const std::vector<CandidateEffect>& candidates,
                       const std::vector<Work*>& work, size_t p, std::vector<ModelPoint>& probes,
                       std::vector<std::vector<double>>& steps, std::vector<Prediction>& probed) {
  std::vector<size_t> at;
  std::vector<ModelPoint> retakes;
  for (size_t i = 0; i < work.size(); ++i) {
    const EffectParameter& e = candidates[work[i]->candidate].parameters[0];
    for (size_t j = 0; j <= p; ++j) {
      if (probed[i * (p + 1) + j].ok) continue;
      ModelPoint q = work[i]->best_point;
      double& x = j < p ? q.base_unit[j] : q.effects.back().values[0];
      const double lo = j < p ? fit.lower[j] : e.lower, hi = j < p ? fit.upper[j] : e.upper;
      x -= steps[i][j];
      if (x < lo || x > hi) continue;  // the point is on a bound: no other side
      at.push_back(i * (p + 1) + j);
      retakes.push_back(q);
    }
  }
  const std::vector<bool> got = EvaluateRetakes(model, at, retakes, probed);
  for (size_t k = 0; k < at.size(); ++k) {
    if (!got[k]) continue;
    const size_t i = at[k] / (p + 1), j = at[k] % (p + 1);
    steps[i][j] = -steps[i][j];
    probes[at[k]] = retakes[k];
  }
}

}  // namespace

std::vector<bool> EvaluateRetakes(ForwardModel& model, const std::vector<size_t>& at,
                                  const std::vector<ModelPoint>& points,
                                  std::vector<Prediction>& probed) {
  if (points.empty()) return {};
  const std::vector<Prediction> got = model.Evaluate(points);
  std::vector<bool> valued(points.size());
  for (size_t k = 0; k < at.size(); ++k) {
    valued[k] = got[k].ok;
    if (got[k].ok)
      probed[at[k]] = got[k];
    else
      probed[at[k]].status += "; on the other side: " + got[k].status;
  }
  return valued;
}

void RecentredRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                     const std::vector<CandidateEffect>& candidates,
                     const std::vector<Work*>& work) {
  const size_t p = fit.point.base_unit.size();
  std::vector<ModelPoint> probes;
  std::vector<std::vector<double>> steps(work.size(), std::vector<double>(p + 1));
  for (size_t i = 0; i < work.size(); ++i) {
    double noise_max = 0;
    for (int k = 0; k < f.n(); ++k)
      noise_max = std::max(noise_max, work[i]->best_prediction.sem[k] / f.sigma(k));
    const double h = calibrate::FiniteDifferenceStep(noise_max);
    for (size_t j = 0; j < p; ++j) {
      ModelPoint q = work[i]->best_point;
      steps[i][j] = q.base_unit[j] + h > fit.upper[j] ? -h : h;
      q.base_unit[j] += steps[i][j];
      probes.push_back(q);
    }
    const EffectParameter& e = candidates[work[i]->candidate].parameters[0];
    ModelPoint q = work[i]->best_point;
    double& t = q.effects.back().values[0];
    steps[i][p] =
        t + h * (e.upper - e.lower) > e.upper ? -h * (e.upper - e.lower) : h * (e.upper - e.lower);
    t += steps[i][p];
    probes.push_back(q);
  }
  std::vector<Prediction> probed = model.Evaluate(probes);
  RetakeOnOtherSide(model, fit, candidates, work, p, probes, steps, probed);
  const std::vector<std::string> names = model.BaseParameterNames();
  std::vector<std::vector<ModelPoint>> tries(work.size());
  for (size_t i = 0; i < work.size(); ++i) {
    Work& w = *work[i];
    Eigen::MatrixXd J = fit.jacobian;  // the added effects' columns are kept
    auto slope = [&](size_t j) {
      return Eigen::VectorXd(
          (ToVector(probed[i * (p + 1) + j].mean) - ToVector(w.best_prediction.mean)) /
          steps[i][j]);
    };
    // A coordinate whose probes on both sides have no value has no derivative here: it is held
    // at its value for this step (its column zeroed for the step's solve, its range closed),
    // rather than stepped on a sensitivity taken elsewhere; the entry's note says so.
    const EffectParameter& e = candidates[w.candidate].parameters[0];
    std::vector<bool> held(p + 1, false);
    for (size_t j = 0; j <= p; ++j) {
      const Prediction& got = probed[i * (p + 1) + j];
      held[j] = !got.ok;
      if (got.ok && j < p) J.col(j) = slope(j);
      if (got.ok && j == p) w.signature = slope(p);
      if (!got.ok) {
        const std::string name =
            j < p ? (j < names.size() ? names[j] : "base " + std::to_string(j)) : e.name;
        w.retake_note += std::string(w.retake_note.empty() ? "" : "; ") +
                         "held for a refit step, " + name +
                         ": no finite-difference probe on either side has a value (" +
                         got.status + ")";
      }
    }
    w.jacobian = J;
    const double t_now = w.best_point.effects.back().values[0];
    FitState here = fit;
    here.point = w.best_point;
    here.point.effects.pop_back();
    const std::vector<double> c = here.Coordinates();
    std::vector<double> lo, hi;
    for (size_t j = 0; j < c.size(); ++j)
      lo.push_back(fit.lower[j] - c[j]), hi.push_back(fit.upper[j] - c[j]);
    const Eigen::VectorXd r =
        StandardisedResiduals(*f.observations, w.best_prediction.mean, f.sigma);
    Eigen::MatrixXd Js = f.sigma.cwiseInverse().asDiagonal() * J;
    for (size_t j = 0; j < p; ++j)
      if (held[j]) Js.col(j).setZero(), lo[j] = 0, hi[j] = 0;
    const Eigen::MatrixXd S = f.sigma.cwiseInverse().cwiseProduct(w.signature);
    const double t_lo = held[p] ? 0 : e.lower - t_now, t_hi = held[p] ? 0 : e.upper - t_now;
    for (size_t j = 0; j <= p; ++j) {  // the best probe, kept aside (header, RefineRefits)
      const Prediction& got = probed[i * (p + 1) + j];
      if (!got.ok) continue;
      const double chi2 = StandardisedResiduals(*f.observations, got.mean, f.sigma).squaredNorm();
      if (chi2 < w.probe_chi2)
        w.probe_chi2 = chi2, w.probe_point = probes[i * (p + 1) + j], w.probe_prediction = got;
    }
    const LinearRefitResult step = LinearRefit(r, Js, S, {t_lo}, {t_hi}, lo, hi);
    // The step is simulated only where the sensitivities just measured promise a fall of at least
    // kRefitChi2Unit (header): below it the candidate has settled by the rule RefineRefits stops
    // on, and the step's runs could only find noise.
    if (r.squaredNorm() - step.chi2 < kRefitChi2Unit) continue;
    for (double scale : {1.0, 0.5}) {  // the Gauss–Newton step, then half of it (below)
      const ActiveEffect added{w.candidate, {t_now + scale * step.t(0)}};
      tries[i].push_back(here.Step(scale * step.delta, &added));
    }
  }
  // Damped Gauss–Newton: where the full step does not lower χ² (noisy or curved sensitivities
  // overshoot), half of it is simulated too. A point without a value counts as not lowering it
  // and is said in the note with its status (a jam is reported as a jam, not as a slow flow).
  std::vector<size_t> pending;
  for (size_t i = 0; i < work.size(); ++i)
    if (!tries[i].empty()) pending.push_back(i);
  for (int attempt = 0; attempt < 2 && !pending.empty(); ++attempt) {
    std::vector<ModelPoint> points;
    for (size_t i : pending) points.push_back(tries[i][attempt]);
    const std::vector<Prediction> got = model.Evaluate(points);
    std::vector<size_t> failed;
    for (size_t k = 0; k < pending.size(); ++k) {
      Work& w = *work[pending[k]];
      const double chi2 =
          got[k].ok ? StandardisedResiduals(*f.observations, got[k].mean, f.sigma).squaredNorm()
                    : INFINITY;
      if (!got[k].ok)
        AddNote(&w, "re-centred refit point " + candidates[w.candidate].parameters[0].name +
                        " = " + ValueText(points[k].effects.back().values[0]) +
                        " had no value (" + got[k].status + ")");
      if (chi2 < w.best_chi2)
        w.best_chi2 = chi2, w.best_point = points[k], w.best_prediction = got[k];
      else
        failed.push_back(pending[k]);
    }
    pending.swap(failed);
  }
}

namespace {

// A simulated point's χ² noise sd without the discrepancy floor, which would only lower it: a
// probe must then beat the refit by more.
double NoiseSdWithoutFloor(const Frame& f, const Prediction& p) {
  if (p.sem.size() != static_cast<size_t>(f.n())) return 0;
  return PointChi2NoiseSd(f, p, StandardisedResiduals(*f.observations, p.mean, f.sigma), 0);
}

// A probe that fits better than the candidate's refit by more than kNoiseSds standard deviations
// of the difference's simulation noise (the ranking's own test that two χ² differ, evidence.h)
// becomes the point the next re-centred step starts from (header, RefineRefits).
void RecentreOnProbe(const Frame& f, Work* w) {
  if (!(w->probe_chi2 < w->best_chi2)) return;
  const double sd = std::hypot(NoiseSdWithoutFloor(f, w->probe_prediction),
                               NoiseSdWithoutFloor(f, w->best_prediction));
  if (w->best_chi2 - w->probe_chi2 <= kNoiseSds * sd) return;
  AddNote(w, "re-centred on a probe with chi2 " + ValueText(w->probe_chi2) + " against " +
                 ValueText(w->best_chi2) + ", beyond " + ValueText(kNoiseSds) +
                 " noise sd of the difference");
  w->best_chi2 = w->probe_chi2, w->best_point = w->probe_point,
  w->best_prediction = w->probe_prediction;
}

}  // namespace

void RefineRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                  const std::vector<CandidateEffect>& candidates, int iterations,
                  std::vector<Work*> active, const DiagnoseProgress& progress) {
  std::erase_if(active,
                [](const Work* w) { return !w->simulated; });  // no refit point to start from
  const std::vector<Work*> all = active;
  for (int k = 0; k < iterations && !active.empty(); ++k) {
    std::vector<double> before;
    for (Work* w : active) {
      RecentreOnProbe(f, w);
      before.push_back(w->best_chi2);
    }
    RecentredRefits(model, f, fit, candidates, active);
    std::vector<Work*> improving;
    std::string line = "re-centred refit round " + std::to_string(k + 1) + ":";
    for (size_t i = 0; i < active.size(); ++i) {
      const bool improved = active[i]->best_chi2 < before[i] - kRefitChi2Unit;
      if (improved) improving.push_back(active[i]);
      line += std::string(i ? ";" : "") + " " + candidates[active[i]->candidate].key + " chi2 " +
              ValueText(before[i]) + " -> " + ValueText(active[i]->best_chi2) +
              (improved ? "" : " (settled)");
    }
    if (progress) progress(line);
    active.swap(improving);
  }
  for (Work* w : all)
    if (w->probe_chi2 < w->best_chi2)
      w->best_chi2 = w->probe_chi2, w->best_point = w->probe_point,
      w->best_prediction = w->probe_prediction;
}

}  // namespace demcal::diagnose::refits
