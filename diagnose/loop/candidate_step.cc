#include "diagnose/loop/candidate_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include "calibrate/sensitivity_refinement.h"
#include "diagnose/loop/refit_work.h"
#include "diagnose/ranking/linear_refit.h"

namespace demcal::diagnose {
namespace {

using namespace refits;  // NOLINT: the step is written in the refit machinery's terms

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A signature run without a value (a funnel that jams at the probe value) is retaken on the
// other side of the fit, at minus the probe clipped to the parameter's range; the signature is
// then the one-sided difference from there, as a re-centred refit's probe is retaken
// (refit_work.h). taken_at: the value each signature is taken at. No value on either side: the
// candidate keeps no signature, and its note says why.
void RetakeSignatures(ForwardModel& model, const std::vector<CandidateEffect>& candidates,
                      const std::vector<int>& remaining, const FitState& fit,
                      std::vector<ModelPoint>& probes, std::vector<Prediction>& probed,
                      std::vector<double>& taken_at) {
  std::vector<size_t> at;
  std::vector<ModelPoint> points;
  for (size_t i = 0; i < remaining.size(); ++i) {
    const EffectParameter& e = candidates[remaining[i]].parameters[0];
    const double other = std::clamp(-e.probe, e.lower, e.upper);
    if (probed[i].ok || other == 0) continue;
    const ActiveEffect added{remaining[i], {other}};
    points.push_back(fit.Step(Eigen::VectorXd::Zero(fit.Fitted()), &added));
    at.push_back(i);
  }
  const std::vector<bool> got = EvaluateRetakes(model, at, points, probed);
  for (size_t k = 0; k < at.size(); ++k)
    if (got[k]) taken_at[at[k]] = points[k].effects.back().values[0], probes[at[k]] = points[k];
}

// A response that is not linear across the fit makes a slope taken on one side a poor guide to
// the other: a heap's angle hardly rises with more rolling resistance than the base assumes
// (it saturates) yet falls steeply with less. A candidate whose linearised refit lands on the
// other side of its signature run (the refit value's sign opposite to the value the signature
// was taken at) has its signature taken again on that side, at minus that value clipped to the
// range, one run per such candidate. Its refit is then the better of the two one-sided refits,
// each held to its own side of the fit (the response modelled as two half-lines meeting at the
// fit), and the signature, the run and `taken_at` are that side's.
void SignatureOnRefitSide(ForwardModel& model, const Frame& f, const FitState& fit,
                          const std::vector<CandidateEffect>& candidates,
                          std::vector<ModelPoint>& probes, std::vector<Prediction>& probed,
                          std::vector<double>& taken_at, std::vector<Work>& work) {
  std::vector<size_t> at;
  std::vector<ModelPoint> points;
  for (size_t i = 0; i < work.size(); ++i) {
    const EffectParameter& e = candidates[work[i].candidate].parameters[0];
    const double other = std::clamp(-taken_at[i], e.lower, e.upper);
    if (!probed[i].ok || taken_at[i] != e.probe || other == 0 || work[i].refit.t.size() == 0 ||
        work[i].refit.t[0] * taken_at[i] >= 0)
      continue;
    const ActiveEffect added{work[i].candidate, {other}};
    points.push_back(fit.Step(Eigen::VectorXd::Zero(f.fitted), &added));
    at.push_back(i);
  }
  if (points.empty()) return;
  const std::vector<Prediction> got = model.Evaluate(points);
  for (size_t k = 0; k < at.size(); ++k) {
    const size_t i = at[k];
    if (!got[k].ok) continue;
    Work& w = work[i];
    const double other = points[k].effects.back().values[0];
    const Eigen::VectorXd signature =
        (ToVector(got[k].mean) - ToVector(fit.prediction.mean)) / other;
    EffectParameter same = candidates[w.candidate].parameters[0], across = same;
    (taken_at[i] > 0 ? same.lower : same.upper) = 0;
    (other > 0 ? across.lower : across.upper) = 0;
    const LinearRefitResult refit_across = Refit(f, across, signature);
    const ModelPoint first_point = w.signature_point;
    const Prediction first_run = w.signature_prediction;
    KeepSignatureRun(f, points[k], got[k], &w);  // a simulated fit of base + effect, as any probe
    if (refit_across.chi2 >= Refit(f, same, w.signature).chi2) {
      w.signature_point = first_point, w.signature_prediction = first_run;
      continue;
    }
    w.signature = signature;
    w.refit = refit_across;
    w.retake_note = "signature taken on the side the refit asks for, at " +
                    std::to_string(other) + " (the run at " + std::to_string(taken_at[i]) +
                    " put the linearised refit on this side)";
    taken_at[i] = other, probes[i] = points[k], probed[i] = got[k];
  }
}

// The candidates of a refit batch with their linearised χ², for the progress log.
std::string Listed(const std::vector<Work*>& batch, const std::vector<CandidateEffect>& candidates) {
  std::ostringstream s;
  s.precision(4);
  for (size_t i = 0; i < batch.size(); ++i)
    s << (i ? ", " : "") << candidates[batch[i]->candidate].key << " (linearised chi2 "
      << batch[i]->refit.chi2 << ")";
  return s.str();
}

// Whether a candidate's simulated refit is significant by the ranking's own test (Record, Fill:
// the evidence with the discrepancy floor at α/K).
bool SimulatedSignificant(const Frame& f, const Work& w,
                          const std::vector<CandidateEffect>& candidates) {
  if (!w.simulated) return false;
  const Eigen::VectorXd r = StandardisedResiduals(*f.observations, w.best_prediction.mean, f.sigma);
  const int k = static_cast<int>(candidates[w.candidate].parameters.size());
  return EvidenceWithFloor(f.r0, r, f.q, k, f.fitted, f.per_candidate).significant;
}

// A base on a bound (bound_alternative.h): the controls that copy a bound parameter stand for it
// beyond its range and are refitted by simulation too (free, so they may step beyond it),
// significant or not — a base within noise on its bound has no significant candidate.
void ForceBoundControls(const std::vector<CandidateEffect>& candidates,
                        const std::vector<BaseBound>& bounds, std::vector<Work>& work,
                        std::vector<Work*>* shortlist) {
  for (Work& w : work) {
    bool copies = false;
    for (const BaseBound& b : bounds)
      copies = copies || candidates[w.candidate].copies == b.coordinate;
    if (copies && candidates[w.candidate].control && w.probe_ok &&
        std::find(shortlist->begin(), shortlist->end(), &w) == shortlist->end())
      shortlist->push_back(&w);
  }
}

// The effects' refits with every bound parameter held at least one finite-difference step
// inside its range (the calibration layer's step for the noise at the fit,
// calibrate/sensitivity_refinement.h: the smallest move off the bound the simulation noise
// resolves). Along a valley where the effect and the bound parameter trade (less rolling
// resistance, lower μs) a free refit has no reason to leave the bound; held inside, it answers
// whether the effect lets the parameter back in with a fit as good. The best `refits` effects
// by their linearised refit under that constraint are simulated, as the shortlist is; they are
// copies, beside the step's ranking, which they do not change.
void RefitInside(ForwardModel& model, const Frame& f, const FitState& fit,
                 const std::vector<CandidateEffect>& candidates,
                 const std::vector<BaseBound>& bounds, const std::vector<Work>& work,
                 const DiagnoseOptions& options, const DiagnoseProgress& progress,
                 StepOutcome* out) {
  double noise_max = 0;
  for (int k = 0; k < f.n(); ++k)
    noise_max = std::max(noise_max, fit.prediction.sem[k] / f.sigma(k));
  const double h = calibrate::FiniteDifferenceStep(noise_max);
  FitState inside = fit;
  for (const BaseBound& b : bounds)
    (b.lower ? inside.lower : inside.upper)[b.coordinate] = b.lower ? h : 1 - h;
  Frame fi = MakeFrame(*f.observations, inside, options);
  fi.per_candidate = f.per_candidate;
  std::vector<Work> held;
  for (const Work& w : work) {
    if (candidates[w.candidate].control || !w.probe_ok) continue;
    held.push_back(w);
    held.back().refit = Refit(fi, candidates[w.candidate].parameters[0], w.signature);
    held.back().simulated = false;
    held.back().retake_note.clear();  // the copy's refits are its own
    // So are its probes: the signature run and the free refit's finite-difference probes sit
    // where the bound parameters were free, not held inside.
    held.back().probe_chi2 = INFINITY;
    held.back().signature_prediction = Prediction{};
  }
  std::sort(held.begin(), held.end(),
            [](const Work& a, const Work& b) { return a.refit.chi2 < b.refit.chi2; });
  if (static_cast<int>(held.size()) > options.dem_refits) held.resize(options.dem_refits);
  std::vector<Work*> active;
  for (Work& w : held) active.push_back(&w);
  SimulateRefits(model, fi, inside, candidates, active);
  SimulateRefits(model, fi, inside, candidates, active);
  RefineRefits(model, fi, inside, candidates, options.extra_refits, active, progress);
  DiagnosisStep rows;
  rows.entries.resize(held.size());
  rows.refit_residuals.resize(held.size());
  for (size_t i = 0; i < held.size(); ++i) {
    Record(fi, held[i], candidates, static_cast<int>(i), &rows);
    out->inside_signatures.push_back(
        std::vector<double>(held[i].signature.data(), held[i].signature.data() + f.n()));
  }
  out->inside_entries = rows.entries;
  out->inside_residuals = rows.refit_residuals;
}

// The fit a simulated refit leads to: its best point and prediction, its sensitivities (the
// re-estimated ones when it has them) with its signature as one more fitted coordinate.
FitState RefittedFit(const Frame& f, const FitState& fit, const Work& w,
                     const std::vector<CandidateEffect>& candidates) {
  FitState next;
  next.point = w.best_point;
  next.prediction = w.best_prediction;
  next.jacobian.resize(f.n(), f.fitted + 1);
  next.jacobian << (w.jacobian.size() ? w.jacobian : fit.jacobian), w.signature;
  next.lower = fit.lower;
  next.upper = fit.upper;
  next.lower.push_back(candidates[w.candidate].parameters[0].lower);
  next.upper.push_back(candidates[w.candidate].parameters[0].upper);
  return next;
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
  std::vector<Prediction> probed = model.Evaluate(probes);
  std::vector<double> taken_at;
  for (int c : remaining) taken_at.push_back(candidates[c].parameters[0].probe);
  RetakeSignatures(model, candidates, remaining, fit, probes, probed, taken_at);
  out.phases.push_back({"signatures", model.SimulationsRun() - sims0, Since(start)});
  std::vector<Work> work;
  for (size_t i = 0; i < remaining.size(); ++i) {
    Work w{remaining[i]};
    w.probe_ok = probed[i].ok;
    w.probe_status = probed[i].status;
    const double probe = candidates[w.candidate].parameters[0].probe;
    if (probed[i].ok) {
      w.signature = (ToVector(probed[i].mean) - ToVector(fit.prediction.mean)) / taken_at[i];
      if (taken_at[i] != probe)
        w.retake_note = "signature taken one-sided at " + std::to_string(taken_at[i]) +
                        ": the run at the probe value had no value";
    } else {
      w.signature = Eigen::VectorXd::Zero(f.n());
    }
    w.refit = Refit(f, candidates[w.candidate].parameters[0], w.signature);
    KeepSignatureRun(f, probes[i], probed[i], &w);
    work.push_back(w);
  }
  SignatureOnRefitSide(model, f, fit, candidates, probes, probed, taken_at, work);
  // The shortlist: significant by the linear prediction, best linear ΔBIC first.
  std::vector<Work*> linear;
  for (Work& w : work)
    if (EvidenceOf(f.chi2_base, w.refit.chi2, 1, f.n(), f.significance).significant)
      linear.push_back(&w);
  std::sort(linear.begin(), linear.end(),
            [](const Work* a, const Work* b) { return a->refit.chi2 < b->refit.chi2; });
  std::vector<Work*> shortlist(
      linear.begin(), linear.begin() + std::min<size_t>(linear.size(), options.dem_refits));
  if (!bounds.empty()) ForceBoundControls(candidates, bounds, work, &shortlist);
  start = Clock::now();
  const int sims1 = model.SimulationsRun();
  for (std::vector<Work*> batch = shortlist; !batch.empty();) {
    if (progress) progress("refitting by simulation: " + Listed(batch, candidates));
    SimulateRefits(model, f, fit, candidates, batch);  // the Gauss–Newton point
    SimulateRefits(model, f, fit, candidates, batch);  // after the secant correction
    RefineRefits(model, f, fit, candidates, options.extra_refits, batch, progress);
    // A simulated refit that is not significant fell short of its linear promise (a response
    // that saturates or turns, a signature far from where the refit lands): its slot goes to the
    // next candidate of the linear ranking, until dem_refits simulated refits are significant,
    // the linear ranking is used up, or 2·dem_refits have been simulated (a cost bound, as
    // dem_refits itself). Each simulated refit is held to α/K as before (K the step's
    // candidates), so simulating more of the K keeps the union bound.
    int held = 0, handed = 0;
    for (const Work* w : shortlist) held += SimulatedSignificant(f, *w, candidates);
    for (const Work* w : linear)
      handed += std::find(shortlist.begin(), shortlist.end(), w) != shortlist.end();
    batch.clear();
    for (Work* w : linear) {
      if (held + static_cast<int>(batch.size()) >= options.dem_refits ||
          handed + static_cast<int>(batch.size()) >= 2 * options.dem_refits)
        break;
      if (std::find(shortlist.begin(), shortlist.end(), w) == shortlist.end()) batch.push_back(w);
    }
    shortlist.insert(shortlist.end(), batch.begin(), batch.end());
  }
  if (!bounds.empty()) {
    if (progress) progress("refitting the effects with the bound parameters held inside");
    RefitInside(model, f, fit, candidates, bounds, work, options, progress, &out);
  }
  out.phases.push_back({"refits", model.SimulationsRun() - sims1, Since(start)});
  out.step.entries.resize(work.size());
  out.step.refit_residuals.resize(work.size());
  for (size_t i = 0; i < work.size(); ++i) {
    Record(f, work[i], candidates, static_cast<int>(i), &out.step);
    out.unit_signatures.push_back(
        std::vector<double>(work[i].signature.data(), work[i].signature.data() + f.n()));
    // The change at the probe value; a signature retaken on the other side, linearised to it.
    const double scale = candidates[work[i].candidate].parameters[0].probe / taken_at[i];
    out.step.signatures.push_back(std::vector<double>(probed[i].mean.size()));
    for (size_t k = 0; k < probed[i].mean.size(); ++k)
      out.step.signatures[i][k] = scale * (probed[i].mean[k] - fit.prediction.mean[k]);
  }
  out.step.ranking = RankCandidates(out.step.entries);
  out.step.simulations = model.SimulationsRun() - sims0;
  if (out.step.ranking.winner < 0) {
    if (const int a = out.step.ranking.set_aside; a >= 0 && !out.step.entries[a].control) {
      out.has_set_aside = true;
      out.set_aside_fit = RefittedFit(f, fit, work[a], candidates);
    }
    return out;
  }
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
  out.next = RefittedFit(f, fit, w, candidates);
  if (out.step.ranking.tied >= 0)
    out.tied_fit = RefittedFit(f, fit, work[out.step.ranking.tied], candidates);
  return out;
}

}  // namespace demcal::diagnose
