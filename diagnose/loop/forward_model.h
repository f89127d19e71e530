#pragma once
// ForwardModel: what the diagnosis loop needs from a simulator, as an interface — the DEM over
// a study (diagnose/dem/study_model.h) or an analytic stand-in in the tests. A model point is
// the base model's fitted parameters (unit cube of the study's parameter space) plus the
// effects switched on, each with its parameter values; a prediction is, per observation (in
// the loop's order), the simulated mean, its standard error and the single-run scatter.
// Replicate seeds are the same for every point (common random numbers), so two points differ
// by their parameters, not by their packings.
//
// Thread-safety: the loop calls one method at a time; implementations parallelise inside.
#include <string>
#include <vector>

#include "diagnose/effects/effect.h"

namespace demcal::diagnose {

// A candidate effect as the loop sees it: its key and parameters (effect.h).
struct CandidateEffect {
  std::string key;
  std::string description;
  std::vector<EffectParameter> parameters;
  // A copy of a fitted base parameter (the sliding-friction control; rolling resistance when the
  // study fits the rolling friction): guarded, never named (ranking.h).
  bool control = false;
  // The index of the fitted base parameter a control copies (−1: none, or not known): the
  // control then stands for that parameter beyond its range when the base fit ends on its
  // bound (bound_alternative.h).
  int copies = -1;
  // The physical mechanism it is a law of (Effect::Mechanism); "": a mechanism of its own.
  std::string mechanism;
};

struct ActiveEffect {
  int candidate = 0;           // index into the candidates
  std::vector<double> values;  // one per parameter
};

struct ModelPoint {
  std::vector<double> base_unit;  // the fitted parameters, unit cube
  std::vector<ActiveEffect> effects;
};

struct Prediction {
  bool ok = false;
  std::string status = "not evaluated";   // "ok" or why not
  std::vector<double> mean, sem, spread;  // per observation; spread = single-run standard deviation
  // Per observation: which simulated quantity it reads (the model's own numbering). Rows with one
  // id read one simulated mean — a scene shared by several table rows, run once (the coating rows
  // of a base the coating does not enter, shared_run_groups.h) — so one simulation error moves
  // them all, and the χ² noise adds their terms before squaring (Chi2NoiseSd). Empty: every row
  // its own quantity.
  std::vector<int> source;
  // Per pair of observations the correlation of their simulation errors (n × n): 1 within a
  // source, the pooled within-run correlation for two observables of one run (the angle and the
  // height of one heap: replicate_pool.h), 0 across runs. Empty: the sources alone.
  std::vector<std::vector<double>> correlation;
};

// The base calibration (Calibration II): best fitted parameters, the prediction there and the
// sensitivities d mean_i / d unit_j (observable units per unit-cube step).
struct BaseCalibration {
  bool ok = false;
  std::string message;
  std::vector<double> base_unit;
  Prediction prediction;
  std::vector<std::vector<double>> jacobian;  // [observation][parameter]
  // The standard errors of jacobian's entries, same shape (empty: not known; zero where a finite
  // difference on common random numbers carries no noise). Identifiability counts a singular
  // value within their size as unresolved (calibrate/jacobian_svd.h, JacobianNoiseFloor).
  std::vector<std::vector<double>> jacobian_sigma;
  std::string termination;                    // the calibration's
  // Settled by the calibration's own criterion: within_noise, converged or out_of_range
  // (calibrate/termination.h); a calibration that stopped on its budget did not.
  bool settled = false;
  int max_evaluations = 0;  // the budget it ran under
};

// The calibration's own verdict that its search ended (not its budget): within_noise,
// converged, out_of_range.
bool SettledTermination(const std::string& termination);

class ForwardModel {
 public:
  virtual ~ForwardModel() = default;
  virtual int BaseParameters() const = 0;
  // The study's calibration with its evaluation budget times budget_scale (1, 2, 4: more
  // evaluations when a fit did not settle; runs already made are read back, not repeated).
  virtual BaseCalibration CalibrateBase(int budget_scale) = 0;
  // Per base parameter: its name and SI units per unit-cube step at the unit point (reports).
  virtual std::vector<std::string> BaseParameterNames() const {
    std::vector<std::string> names;
    for (int j = 0; j < BaseParameters(); ++j)
      names.push_back(std::to_string(j)), names.back().insert(0, "u");
    return names;
  }
  virtual std::vector<double> BaseSiPerUnit(const std::vector<double>&) const {
    return std::vector<double>(BaseParameters(), 1.0);
  }
  // One prediction per point, in order; points are run side by side.
  virtual std::vector<Prediction> Evaluate(const std::vector<ModelPoint>& points) = 0;
  // Simulations (replicate runs) made so far, and those read back from a journal.
  virtual int SimulationsRun() const = 0;
  virtual int SimulationsReused() const { return 0; }
};

}  // namespace demcal::diagnose
