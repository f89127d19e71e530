#pragma once
// The refit machinery of a candidate step (candidate_step.h): the step's frame (fixed sigmas,
// residuals at the fit, standardised sensitivities), a candidate under way (its signature and
// refits), the simulated Gauss–Newton refits, the re-centred refit points and the ranking entry
// each candidate becomes. Internal to the loop (diagnose/loop/); the why of each step is at its
// declaration below and in docs/diagnose.md "What it does".
//
// Thread-safety: runs on the calling thread; the model parallelises.
#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "diagnose/loop/diagnosis.h"
#include "diagnose/loop/fit_state.h"
#include "diagnose/ranking/linear_refit.h"

namespace demcal::diagnose::refits {

// The least fall of a candidate's best χ² that counts as progress of its refit: one standard
// deviation of a fitted parameter, the profile-likelihood unit (a smaller change is noise).
// RefineRefits stops a candidate whose re-centred point fell by less; RecentredRefits does not
// simulate a step its fresh sensitivities promise less from.
constexpr double kRefitChi2Unit = 1.0;

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
  // The best of its simulated probes — the signature run (candidate_step.cc) and the
  // finite-difference probes — when one fits better than every refit point: RefineRefits makes
  // it the refit once the re-centred points end (header, RefineRefits).
  ModelPoint probe_point;
  Prediction probe_prediction;
  double probe_chi2 = INFINITY;
  // Set when a run without a value was retaken on the other side (the signature,
  // candidate_step.cc) or a re-centred step held a coordinate whose finite-difference probes on
  // both sides had no value (RecentredRefits): said in the entry's note.
  std::string retake_note;
  bool simulated = false;
  bool probe_ok = true;
  std::string probe_status;
  // The signature run as a simulated point of base + effect (the fit's base parameters, the
  // effect at the value the signature was taken at); ok false when it had no value.
  ModelPoint signature_point;
  Prediction signature_prediction;
};

// Keeps the signature run aside as a probe of the refit (Work::probe_point): it is a simulated
// fit of base + effect like any finite-difference probe, and the refit compares maximised
// likelihoods, so the best simulated point of the candidate is its refit, the base's being the
// best of every point its calibration simulated.
void KeepSignatureRun(const Frame& f, const ModelPoint& point, const Prediction& run, Work* w);

Eigen::VectorXd ToVector(const std::vector<double>& v);

Frame MakeFrame(const std::vector<Observation>& observations, const FitState& fit,
                const DiagnoseOptions& o);

LinearRefitResult Refit(const Frame& f, const EffectParameter& p, const Eigen::VectorXd& signature);

// The evidence with the discrepancy floor in the variance (evidence.h), at the significance
// over the step's candidates: the step names at most one of K, so each is held to α/K and a
// model that fits names none with probability ≥ 1 − α (Bonferroni).
void Fill(const Frame& f, const Work& w, const std::vector<CandidateEffect>& candidates,
          const Eigen::VectorXd& r, RankingEntry* e);

// Runs without a value (probed[at[k]]) retaken at points[k], in one batch: a retake with a value
// replaces the run; one without appends its status to the run's ("; on the other side: ...").
// Per retake, whether it got a value. The callers choose the other-side point: the signature
// at minus the probe value (candidate_step.cc), a finite-difference probe one step back
// (RecentredRefits).
std::vector<bool> EvaluateRetakes(ForwardModel& model, const std::vector<size_t>& at,
                                  const std::vector<ModelPoint>& points,
                                  std::vector<Prediction>& probed);

// Simulates the Gauss–Newton point of each candidate; keeps it when it beats the best so far
// and corrects the signature by the secant through it. A point without a value (a jammed
// funnel, a run that blew up) is no better than the fit, so, as in damped Gauss–Newton, half
// the step toward the fit is simulated once in its place; the secant is then taken through
// the half step. A candidate whose refit points have no value on either try keeps its
// signature run as its simulated point (and RefineRefits re-centres from there), rather than
// leaving the ranking on a linearisation the runs could not check: a run without a value is
// evidence neither for nor against the effect (the data discharged, the simulation did not
// say how this value would). Each failure is said in the entry's note.
void SimulateRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                    const std::vector<CandidateEffect>& candidates, std::vector<Work*>& work);

// Entry i of the step and its residuals at the refit (simulated when there is one).
void Record(const Frame& f, const Work& w, const std::vector<CandidateEffect>& candidates, int i,
            DiagnosisStep* step);

// A refit point of each candidate from its own best point rather than from the base fit: the
// sensitivities to the base parameters and to the effect are re-estimated there by finite
// differences (one run each, in the unit cube the step of the calibration layer's rule for this
// simulation noise, inward at a bound), then one Gauss–Newton step of base + effect is
// simulated, unless those sensitivities promise a fall of χ² below kRefitChi2Unit (a clipped
// step can even promise a rise): then the candidate has settled, and nothing more is simulated. A
// probe without a value is retaken one step on the other side of the point (a one-sided backward
// difference); a coordinate with no value on either side is held for that step, said in the entry's
// note. The base fit's sensitivities can be wrong far from it (a friction whose heap angle
// saturates at the refit point but not at the base would keep pulling the refit the wrong way), and
// a secant signature inherits their error. The best finite-difference probe is kept aside
// (Work::probe_point).
void RecentredRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                     const std::vector<CandidateEffect>& candidates,
                     const std::vector<Work*>& work);

// Further re-centred refit points for each candidate, while each lowers its best χ² by at least
// kRefitChi2Unit, at most `iterations` more each. ΔBIC and the
// likelihood ratio compare maximised likelihoods: a candidate still far from its minimum after
// two points (a strongly nonlinear signature, a refit along a valley) would lose to one that
// happened to converge faster. When the points end, a probe (the signature run, a
// finite-difference probe) that fits better than every refit point becomes the refit: each probe is
// a simulated fit of base + effect, and the likelihood ratio and ΔBIC compare maximised
// likelihoods, the base's being the best of every point its calibration simulated (the
// `adhesion_coating` twin: refit points 11.05–20.0, a probe 9.11, each with a χ² noise sd of 4.7).
// A probe re-centres the points only when it is lower than the refit beyond kNoiseSds standard
// deviations of the difference's simulation noise (evidence.h, the ranking's test that two χ²
// differ; the floor left out, which would only lower the noise): a probe lower by its noise is
// no better centre, and from one the next points stop at once (stepping from such a probe, the
// cross-engine `wide_psd` size refit ended at χ² 61.6 where the steps alone reach 43.8), while
// steps from a refit point far worse than a probe spend runs reaching what the probe already
// has (`crossengine_wide_psd_fit_rolling`: four re-centred rounds took the size refit from 115
// to 30 beside its signature run at 17, which then became the refit). Checked at the start of
// each round; the entry's note says when it happened. Each round's χ² per candidate, before and
// after, goes to `progress` (stderr in the CLI), "(settled)" for a candidate that stops there.
void RefineRefits(ForwardModel& model, const Frame& f, const FitState& fit,
                  const std::vector<CandidateEffect>& candidates, int iterations,
                  std::vector<Work*> active, const DiagnoseProgress& progress = {});

}  // namespace demcal::diagnose::refits
