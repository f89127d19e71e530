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
  std::string status = "not evaluated";  // "ok" or why not
  std::vector<double> mean, sem, spread;  // per observation; spread = single-run standard deviation
};

// The base calibration (Calibration II): best fitted parameters, the prediction there and the
// sensitivities d mean_i / d unit_j (observable units per unit-cube step).
struct BaseCalibration {
  bool ok = false;
  std::string message;
  std::vector<double> base_unit;
  Prediction prediction;
  std::vector<std::vector<double>> jacobian;  // [observation][parameter]
  std::string termination;                     // the calibration's
};

class ForwardModel {
 public:
  virtual ~ForwardModel() = default;
  virtual int BaseParameters() const = 0;
  virtual BaseCalibration CalibrateBase() = 0;
  // One prediction per point, in order; points are run side by side.
  virtual std::vector<Prediction> Evaluate(const std::vector<ModelPoint>& points) = 0;
  // Simulations (replicate runs) made so far, and those read back from a journal.
  virtual int SimulationsRun() const = 0;
  virtual int SimulationsReused() const { return 0; }
};

}  // namespace demcal::diagnose
