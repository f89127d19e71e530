#pragma once
// SettleBase: a base fit worth diagnosing (docs/diagnose/base_fit.md). The
// study's calibration is run with its own budget; when it ends on that budget rather than by its
// own criterion (calibrate/termination.h: within_noise, converged, out_of_range) it is run again
// with twice the budget, then four times (kMaxBaseBudgetScale) — the journal reads back the runs
// already made, so each extension costs only its new candidates. It also counts as settled when
// twice the budget lowered the best fit's χ² by less than StagnationMargin (below: a noisy DEM
// objective may never meet the optimiser's tolerance, yet more evaluations no longer move the
// fit by more than its own noise). A base within noise (no gap at the significance) is
// not extended: more budget could only lower its χ², and "no missing effect" stands — unless
// settle_within_noise (the screen without a gap, diagnosis.h step 2): a candidate's refit also
// refits the base parameters, so an unsettled base's own slack would count as evidence for
// every candidate; the base is then extended as with a gap. A fit that
// has not settled then
// is reported as such and no effect is ranked on it: an unsettled base leaves a gap the
// calibration itself would have closed, and any effect "explains" it.
// A base settled by stagnation is then checked by its own linearised step (base_step.h): when the
// sensitivities its calibration estimated predict a drop of χ² beyond what the simulation noise
// alone would predict (BaseStepThreshold), the step is simulated (then half of it, if the
// whole is no better), at most kMaxBaseSteps times, and the base moves to a simulated point
// whose χ² is lower than the fit's: the calibration's own rule for its best candidate (the
// lowest cost), applied to one more candidate. The optimiser's own verdicts (within_noise,
// converged) are not second-guessed: stagnation is this file's inference.
// At the settled fit, the identifiability of the base parameters (calibrate/identifiability.h on
// the standardised sensitivities): a combination the data leave undetermined is reported
// before any effect is named, since an effect traded against it is not told apart from it.
//
//   BaseFit b = SettleBase(model, observations, 1.0, 0.01, progress);
//   if (!b.base.settled) ...;  // DiagnosisTermination::kBaseUnsettled
//
// Thread-safety: runs on the calling thread; the model parallelises.
#include <functional>
#include <string>
#include <vector>

#include "calibrate/identifiability.h"
#include "diagnose/gap/observation.h"
#include "diagnose/loop/forward_model.h"

namespace demcal::diagnose {

// The base budget is extended to at most this multiple of the study's: a cost bound (each
// doubling at most doubles the base calibration's runs), not a statistical threshold.
inline constexpr int kMaxBaseBudgetScale = 4;

// Stagnation: the drop of the best fit's χ² from one budget to twice it that still counts as no
// progress, max(1, kNoiseSds·√(sd_before² + sd_after²)). 1 is one standard deviation of a
// fitted parameter (the profile-likelihood unit). sd is each fit's χ² noise from its simulated
// means' standard errors (BaseChi2, base_noise.h: rows that read one simulated mean added
// together, as one shared error moves them together): on an objective whose simulation noise moves
// χ² by more than 1, the best of twice as many noisy candidates is lower by the luck of its
// draws alone (the minimum of more draws), so a drop within two standard deviations of the
// difference is not evidence that the search still moves — the same kNoiseSds the ranking uses
// to tell two simulated refits apart.
double StagnationMargin(double noise_sd_before, double noise_sd_after);

// The linearised steps simulated at most to check a stagnated base: a cost bound (one base
// point each), not a statistical threshold. Two lets a step confirmed from a far-off start be
// followed by one from the point it reached, with the same sensitivities.
inline constexpr int kMaxBaseSteps = 2;

// The predicted drop of χ² a linearised step must exceed to be simulated: max(1, m² · the χ²_rank
// quantile at 1 − significance), m the largest sem/σ (base_step.h: the drop the simulation noise
// alone gives with nothing to find, at the diagnosis' significance), 1 the profile-likelihood
// unit (a drop below one parameter standard deviation is no evidence the fit is off its optimum).
double BaseStepThreshold(int rank, double max_noise_per_sigma, double significance);

// One simulated linearised step of the base (base_step.h).
struct BaseStepRecord {
  std::vector<double> unit;  // the point simulated
  double fraction = 1;       // of the linearised step (0.5: the damped retry)
  double chi2_before = 0, chi2_predicted = 0, chi2_simulated = 0;
  double threshold = 0;   // BaseStepThreshold: the predicted drop exceeded it
  bool accepted = false;  // the base moved there (chi2_simulated < chi2_before)
};

// A base parameter fitted onto a bound of the study's range: its coordinate and which bound.
struct BaseBound {
  int coordinate = 0;
  bool lower = true;
};

struct BaseFit {
  BaseCalibration base;
  int budget_scale = 1;       // the study's budget times this was used
  bool within_noise = false;  // not settled, not extended: no gap at this fit
  bool stagnated = false;     // settled because twice the budget lowered χ² by less than
                              // stagnation_margin (StagnationMargin)
  double stagnation_margin = 0;
  std::vector<double> chi2_rounds;  // the best fit's χ² of every unsettled round, in order
  std::vector<double> chi2_noise_sd_rounds;  // and its simulation noise sd (BaseChi2)
  std::vector<BaseStepRecord> steps;  // the linearised steps simulated after stagnation
  calibrate::IdentifiabilityReport identifiability;
  // Base parameters whose fit ended on a bound of the study's range: "mu_s_BP_BP at its lower
  // bound". The data may ask for a value beyond the range, and an effect that moves the
  // observables as that parameter does can be absorbed there, so a verdict on this fit says so.
  std::vector<std::string> at_bound;
  std::vector<BaseBound> bounds;  // the same parameters, as coordinates
  std::string summary;  // in words: settled or not, with which budget, what is undetermined
};

BaseFit SettleBase(ForwardModel& model, const std::vector<Observation>& observations,
                   double floor_factor, double significance,
                   const std::function<void(const std::string&)>& progress,
                   bool settle_within_noise = false);

}  // namespace demcal::diagnose
