#pragma once
// Observation: one measured value of a diagnosis (a row of the tidy measurement table that a
// study target selected) with the model's simulated value beside it. Its standardised residual
// divides by every noise that can make model and measurement differ without a missing effect:
//   sigma² = u_measured² + sem_simulated² + floor²
// u_measured is the table's (or the study's) standard uncertainty, sem_simulated the standard
// error of the simulated mean over its replicates, and floor the model-discrepancy noise floor
// (docs/diagnose/thresholds.md: by default the single-run scatter of the simulation over the square
// root of the repeats the measured value is the mean of: a value measured on one packing differs
// from the right model's mean by about one packing's scatter, a mean of n packings by 1/√n of it).
// Units: the observable's (SI unless its name says otherwise).
//
//   Observation o{"angle_deg BP (coating=1.5)", "angle_deg", {{"coating_PEG_wt_pct", "1.5"}},
//                 31.2, 1.0};
//   o.simulated = 28.0; o.sem = 0.4; o.floor = 0.9;
//   o.Residual();  // (28 − 31.2) / sqrt(1 + 0.16 + 0.81)
//
// Thread-safety: a plain value.
#include <cmath>
#include <string>
#include <vector>

#include "calibrate/condition.h"

namespace demcal::diagnose {

struct Observation {
  std::string name;
  std::string observable;          // registered name, unit in it ("angle_deg")
  calibrate::Condition condition;  // the table row's condition columns
  double measured = 0;
  double uncertainty = 1;  // measurement standard uncertainty, > 0
  double simulated = 0;
  double sem = 0;          // simulation standard error of the mean, >= 0
  double floor = 0;        // model-discrepancy noise floor, >= 0
  double scatter = 0;      // the simulation's single-run scatter (the floors' unit), >= 0
  int repeats = 0;         // packings the measured value is the mean of (0: not stated, one)
  std::string experiment;  // the experiment file that measures it ("" when not known)
  // The simulated quantity it reads (Prediction::source); rows with one source share its
  // simulation error. −1: its own.
  int source = -1;
  // Its row of the prediction's error correlation (Prediction::correlation); empty: its source's.
  std::vector<double> correlation;

  double Sigma() const { return std::sqrt(uncertainty * uncertainty + sem * sem + floor * floor); }
  double Residual() const { return (simulated - measured) / Sigma(); }
};

// The standardised residuals of a list, in order.
std::vector<double> Residuals(const std::vector<Observation>& observations);
// Their sources, in order (Chi2NoiseSd's grouping).
std::vector<int> Sources(const std::vector<Observation>& observations);
// Their rows of the error correlation, in order (empty rows where not known).
std::vector<std::vector<double>> Correlations(const std::vector<Observation>& observations);

}  // namespace demcal::diagnose
