#include "diagnose/loop/candidate_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include "calibrate/sensitivity_refinement.h"
#include "diagnose/ranking/linear_refit.h"

namespace demcal::diagnose {
namespace {

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Eigen::VectorXd ToVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size());
}

// What a step works with: the fixed sigmas, the residuals at the fit and the standardised J.
struct Frame {
  const std::vector<Observation>* observations;
  Eigen::VectorXd sigma, r0;
  Eigen::VectorXd q;  // single-run scatter per sigma (the estimated floor's shape)
  Eigen::MatrixXd J;
  std::vector<double> delta_lower, delta_upper;
  int fitted = 0;
  double chi2_base = 0;
  double significance = 0.01;
  double per_candidate = 0.01;  // significance over the candidates of the step (Bonferroni)
  int n() const { return static_cast<int>(r0.size()); }
};

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

// A candidate under way: its raw signature per unit parameter, its refits so far.
struct Work {
  int candidate = 0;
  Eigen::VectorXd signature;  // raw units per unit of the parameter
  Eigen::MatrixXd
      jacobian;  // the base sensitivities re-estimated near its refit (empty: the fit's)
  LinearRefitResult refit;
  ModelPoint best_point;
  Prediction best_prediction;
  double best_chi2 = 0;
  bool simulated = false;
  bool probe_ok = true;
  std::string probe_status;
};

LinearRefitResult Refit(const Frame& f, const EffectParameter& p,
                        const Eigen::VectorXd& signature) {
  const Eigen::MatrixXd S = f.sigma.cwiseInverse().cwiseProduct(signature);
  return LinearRefit(f.r0, f.J, S, {p.lower}, {p.upper}, f.delta_lower, f.delta_upper);
}

// The evidence with the discrepancy floor in the variance (evidence.h), at the significance
// over the step's candidates: the step names at most one of K, so each is held to α/K and a
// model that fits names none with probability ≥ 1 − α (Bonferroni).
void Fill(const Frame& f, const Work& w, const std::vector<CandidateEffect>& candidates,
          const Eigen::VectorXd& r, RankingEntry* e) {
  const int k = static_cast<int>(candidates[w.candidate].parameters.size());
  e->candidate = w.candidate;
  e->key = candidates[w.candidate].key;
  e->chi2_linear = w.refit.chi2;
  e->linear = EvidenceWithFloor(f.r0, w.refit.residuals, f.q, k, f.fitted, f.per_candidate);
  e->simulated = w.simulated;
  e->chi2 = w.simulated ? w.best_chi2 : w.refit.chi2;
  e->evidence = EvidenceWithFloor(f.r0, r, f.q, k, f.fitted, f.per_candidate);
  // The simulated refit's χ² moves with its points' simulation noise (evidence.h, ToldApart):
  // the ranking does not tell two candidates apart by less than that.
  if (w.simulated && w.best_prediction.sem.size() == static_cast<size_t>(f.n())) {
    const Eigen::VectorXd u = ToVector(w.best_prediction.sem).cwiseQuotient(f.sigma);
    e->evidence.chi2_noise_sd = Chi2NoiseSd(r, u, f.q, e->evidence.floor);
  }
  e->chi2_per_dof = e->chi2 / std::max(1, f.n() - f.fitted - k);
  e->control = candidates[w.candidate].control;
  if (w.simulated) e->base_unit = w.best_point.base_unit;
  e->signature_match = SignatureMatch(f.r0, f.J, f.sigma.cwiseInverse().cwiseProduct(w.signature));
  if (w.best_point.effects.empty())
    e->values = {w.refit.t(0)};
  else
    e->values = w.best_point.effects.back().values;
}

// Simulates the Gauss–Newton point of each candidate; keeps it when it beats the best so far
// and corrects the signature by the secant through it.
void SimulateRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                    const std::vector<CandidateEffect>& candidates, std::vector<Work*>& work) {
  std::vector<ModelPoint> points;
  for (Work* w : work) {
    const ActiveEffect added{w->candidate, {w->refit.t(0)}};
    points.push_back(fit.Step(w->refit.delta, &added));
  }
  const std::vector<Prediction> got = model.Evaluate(points);
  for (size_t i = 0; i < work.size(); ++i) {
    Work& w = *work[i];
    if (!got[i].ok) continue;
    const double chi2 = StandardisedResiduals(*f.observations, got[i].mean, f.sigma).squaredNorm();
    if (!w.simulated || chi2 < w.best_chi2) {
      w.best_chi2 = chi2, w.best_point = points[i], w.best_prediction = got[i], w.simulated = true;
    }
    const double t = w.refit.t(0);
    if (t != 0) {
      const Eigen::VectorXd moved =
          ToVector(got[i].mean) - ToVector(fit.prediction.mean) - fit.jacobian * w.refit.delta;
      w.signature = moved / t;
    }
    w.refit = Refit(f, candidates[w.candidate].parameters[0], w.signature);
  }
}

// Entry i of the step and its residuals at the refit (simulated when there is one).
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
  step->refit_residuals[i].assign(r.data(), r.data() + r.size());
}

// A refit point of each candidate from its own best point rather than from the base fit: the
// sensitivities to the base parameters and to the effect are re-estimated there by finite
// differences (one run each, in the unit cube the step of the calibration layer's rule for this
// simulation noise, inward at a bound), then one Gauss–Newton step of base + effect is
// simulated. The base fit's sensitivities can be wrong far from it (a friction whose heap angle
// saturates at the refit point but not at the base would keep pulling the refit the wrong
// way), and a secant signature inherits their error.
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
  const std::vector<Prediction> probed = model.Evaluate(probes);
  std::vector<std::vector<ModelPoint>> tries(work.size());
  for (size_t i = 0; i < work.size(); ++i) {
    Work& w = *work[i];
    Eigen::MatrixXd J = fit.jacobian;  // the added effects' columns are kept
    auto slope = [&](size_t j) {
      return Eigen::VectorXd(
          (ToVector(probed[i * (p + 1) + j].mean) - ToVector(w.best_prediction.mean)) /
          steps[i][j]);
    };
    for (size_t j = 0; j < p; ++j)
      if (probed[i * (p + 1) + j].ok) J.col(j) = slope(j);
    if (probed[i * (p + 1) + p].ok) w.signature = slope(p);
    w.jacobian = J;
    const EffectParameter& e = candidates[w.candidate].parameters[0];
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
    const Eigen::MatrixXd Js = f.sigma.cwiseInverse().asDiagonal() * J;
    const Eigen::MatrixXd S = f.sigma.cwiseInverse().cwiseProduct(w.signature);
    const LinearRefitResult step =
        LinearRefit(r, Js, S, {e.lower - t_now}, {e.upper - t_now}, lo, hi);
    for (double scale : {1.0, 0.5}) {  // the Gauss–Newton step, then half of it (below)
      const ActiveEffect added{w.candidate, {t_now + scale * step.t(0)}};
      tries[i].push_back(here.Step(scale * step.delta, &added));
    }
  }
  // Damped Gauss–Newton: where the full step does not lower χ² (noisy or curved sensitivities
  // overshoot), half of it is simulated too.
  std::vector<size_t> pending(work.size());
  std::iota(pending.begin(), pending.end(), 0);
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
      if (chi2 < w.best_chi2)
        w.best_chi2 = chi2, w.best_point = points[k], w.best_prediction = got[k];
      else
        failed.push_back(pending[k]);
    }
    pending.swap(failed);
  }
}

// Further re-centred refit points for each candidate, while each lowers its best χ² by at least
// 1 (a change of χ² below 1 is within one standard deviation of a fitted parameter, the
// profile-likelihood unit, so it is noise), at most `iterations` more each. ΔBIC and the
// likelihood ratio compare maximised likelihoods: a candidate still far from its minimum after
// two points (a strongly nonlinear signature, a refit along a valley) would lose to one that
// happened to converge faster.
void RefineRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                  const std::vector<CandidateEffect>& candidates, int iterations,
                  std::vector<Work*> active) {
  std::erase_if(active,
                [](const Work* w) { return !w->simulated; });  // no refit point to start from
  for (int k = 0; k < iterations && !active.empty(); ++k) {
    std::vector<double> before;
    for (const Work* w : active) before.push_back(w->best_chi2);
    RecentredRefits(model, f, fit, candidates, active);
    std::vector<Work*> improving;
    for (size_t i = 0; i < active.size(); ++i)
      if (active[i]->best_chi2 < before[i] - 1) improving.push_back(active[i]);
    active.swap(improving);
  }
}

// A base on a bound (bound_alternative.h): the controls that copy a bound parameter (they stand
// for it beyond its range) and the effects whose linearised refit moves every bound parameter
// inward are refitted by simulation too, significant or not — a base within noise on its bound
// has no significant candidate, yet the two explanations must be compared on real refits. The
// effects are taken best linear χ² first, at most `refits` of them in all, like the shortlist.
void BoundShortlist(const std::vector<CandidateEffect>& candidates,
                    const std::vector<BaseBound>& bounds, int refits, std::vector<Work>& work,
                    std::vector<Work*>* shortlist) {
  auto listed = [shortlist](Work* w) {
    return std::find(shortlist->begin(), shortlist->end(), w) != shortlist->end();
  };
  std::vector<Work*> inward;
  int effects = 0;
  for (Work& w : work) {
    const CandidateEffect& c = candidates[w.candidate];
    effects += listed(&w) && !c.control ? 1 : 0;
    bool copies = false, in = w.probe_ok && !c.control;
    for (const BaseBound& b : bounds) {
      copies = copies || c.copies == b.coordinate;
      in = in && (b.lower ? w.refit.delta(b.coordinate) > 0 : w.refit.delta(b.coordinate) < 0);
    }
    if (c.control && copies && w.probe_ok && !listed(&w)) shortlist->push_back(&w);
    if (in && !listed(&w)) inward.push_back(&w);
  }
  std::sort(inward.begin(), inward.end(),
            [](const Work* a, const Work* b) { return a->refit.chi2 < b->refit.chi2; });
  for (size_t i = 0; i < inward.size() && effects < refits; ++i, ++effects)
    shortlist->push_back(inward[i]);
}

}  // namespace

StepOutcome RunCandidateStep(ForwardModel& model, const std::vector<Observation>& observations,
                             const std::vector<CandidateEffect>& candidates,
                             const std::vector<int>& remaining, const FitState& fit,
                             const DiagnoseOptions& options, const DiagnoseProgress& progress,
                             const std::vector<BaseBound>& bounds) {
  StepOutcome out;
  Frame f = MakeFrame(observations, fit, options);
  f.per_candidate = options.significance / std::max<size_t>(1, remaining.size());
  const int sims0 = model.SimulationsRun();
  auto start = Clock::now();
  std::vector<ModelPoint> probes;
  for (int c : remaining) {
    const ActiveEffect added{c, {candidates[c].parameters[0].probe}};
    probes.push_back(fit.Step(Eigen::VectorXd::Zero(f.fitted), &added));
  }
  if (progress)
    progress("signatures of " + std::to_string(remaining.size()) + " candidate effects");
  const std::vector<Prediction> probed = model.Evaluate(probes);
  out.phases.push_back({"signatures", model.SimulationsRun() - sims0, Since(start)});
  std::vector<Work> work;
  for (size_t i = 0; i < remaining.size(); ++i) {
    Work w{remaining[i]};
    w.probe_ok = probed[i].ok;
    w.probe_status = probed[i].status;
    if (probed[i].ok) {
      w.signature = (ToVector(probed[i].mean) - ToVector(fit.prediction.mean)) /
                    candidates[w.candidate].parameters[0].probe;
    } else {
      w.signature = Eigen::VectorXd::Zero(f.n());
    }
    w.refit = Refit(f, candidates[w.candidate].parameters[0], w.signature);
    work.push_back(w);
  }
  // The shortlist: significant by the linear prediction, best linear ΔBIC first.
  std::vector<Work*> shortlist;
  for (Work& w : work)
    if (EvidenceOf(f.chi2_base, w.refit.chi2, 1, f.n(), f.significance).significant)
      shortlist.push_back(&w);
  std::sort(shortlist.begin(), shortlist.end(),
            [](const Work* a, const Work* b) { return a->refit.chi2 < b->refit.chi2; });
  if (static_cast<int>(shortlist.size()) > options.dem_refits) shortlist.resize(options.dem_refits);
  if (!bounds.empty()) BoundShortlist(candidates, bounds, options.dem_refits, work, &shortlist);
  start = Clock::now();
  const int sims1 = model.SimulationsRun();
  if (!shortlist.empty()) {
    if (progress)
      progress("refitting " + std::to_string(shortlist.size()) + " candidates by simulation");
    SimulateRefits(model, f, fit, candidates, shortlist);  // the Gauss–Newton point
    SimulateRefits(model, f, fit, candidates, shortlist);  // after the secant correction
    RefineRefits(model, f, fit, candidates, options.extra_refits, shortlist);
  }
  out.phases.push_back({"refits", model.SimulationsRun() - sims1, Since(start)});
  out.step.entries.resize(work.size());
  out.step.refit_residuals.resize(work.size());
  for (size_t i = 0; i < work.size(); ++i) {
    Record(f, work[i], candidates, static_cast<int>(i), &out.step);
    out.unit_signatures.push_back(std::vector<double>(work[i].signature.data(),
                                                      work[i].signature.data() + f.n()));
    out.step.signatures.push_back(std::vector<double>(probed[i].mean.size()));
    for (size_t k = 0; k < probed[i].mean.size(); ++k)
      out.step.signatures[i][k] = probed[i].mean[k] - fit.prediction.mean[k];
  }
  out.step.ranking = RankCandidates(out.step.entries);
  out.step.simulations = model.SimulationsRun() - sims0;
  if (out.step.ranking.winner < 0) return out;
  const int win = out.step.ranking.winner;
  const Work& w = work[win];
  int runner = -1;
  for (int i : out.step.ranking.order)
    if (i != win) {
      runner = i;
      break;
    }
  const Eigen::VectorXd rw = ToVector(out.step.refit_residuals[win]);
  const Eigen::VectorXd rr =
      runner >= 0 ? ToVector(out.step.refit_residuals[runner]) : Eigen::VectorXd();
  out.step.carried = Carried(f.r0, observations, rw, runner >= 0 ? &rr : nullptr);
  if (out.step.ranking.tied >= 0) {
    const int t = out.step.ranking.tied;
    const Eigen::VectorXd sa = f.sigma.cwiseInverse().cwiseProduct(work[win].signature);
    const Eigen::VectorXd sb = f.sigma.cwiseInverse().cwiseProduct(work[t].signature);
    out.step.separating =
        FindSeparatingMeasurement(f.J, sa, sb, rw, ToVector(out.step.refit_residuals[t]), f.sigma,
                                  observations, out.step.entries[win].key, out.step.entries[t].key);
  }
  out.has_winner = true;
  out.next.point = w.best_point;
  out.next.prediction = w.best_prediction;
  out.next.jacobian.resize(f.n(), f.fitted + 1);
  out.next.jacobian << (w.jacobian.size() ? w.jacobian : fit.jacobian), w.signature;
  out.next.lower = fit.lower;
  out.next.upper = fit.upper;
  out.next.lower.push_back(candidates[w.candidate].parameters[0].lower);
  out.next.upper.push_back(candidates[w.candidate].parameters[0].upper);
  return out;
}

}  // namespace demcal::diagnose
