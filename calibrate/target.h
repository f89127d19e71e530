#pragma once
// Target: one measured value a calibration matches — an observable of a virtual experiment
// under a condition, with the measurement's value, its standard uncertainty and provenance.
// A calibration takes a list of them; the residual of target k at a candidate is
// (simulated_k − value) / uncertainty (standardised).
//
//   std::vector<Target> targets = {{"aor_BP", "angle_deg", 34.2, 0.8, "alizadeh2018 Table 3"},
//                                  {"discharge", "discharge_time_s", 12.1, 0.3, "bench 2024-05"}};
//
// Thread-safety: a plain value.
#include <string>

namespace demcal::calibrate {

struct Target {
  std::string name;        // unique within a study, e.g. "aor_EP_w2"
  std::string observable;  // e.g. "angle_deg", "discharge_time_s"
  double value = 0;        // in the observable's unit (SI unless the name says otherwise)
  double uncertainty = 1;  // one standard deviation of the measurement, > 0
  std::string source;      // provenance: dataset file and row, or paper/table/figure
};

}  // namespace demcal::calibrate
