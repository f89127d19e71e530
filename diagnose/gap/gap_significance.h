#pragma once
// TestGap: does a calibrated model still disagree with the measurements by more than their
// noise, where, and along which covariate?
//  - chi² = Σ r_i² of the standardised residuals (observation.h) against a chi-square with
//    dof = n − p degrees of freedom (p: parameters fitted to these n values). A gap exists when
//    P(χ²_dof > chi²) < significance: the residuals are larger than noise at the stated level.
//    With C numeric condition columns, also when the pooled residual trend along one of them has
//    p < significance/(2C), the chi-square then at significance/2 (Bonferroni over both tests).
//  - Where: the observations with |r_i| above the two-sided normal quantile at significance/n
//    (Bonferroni over the n residuals, so a clean fit flags none with probability 1 − α), and
//    chi² per observable (which kind of measurement carries the misfit).
//  - Trends (covariate_trend.h): the weighted slope of r along every numeric condition column.
// The significance is the user's (default 0.01: a one-in-a-hundred false alarm on a model that
// fits, chosen before seeing any data; docs/diagnose/thresholds.md). Nothing here depends on a
// dataset.
//
//   GapReport g = TestGap(observations, 1, {.significance = 0.01});
//   if (g.gap_detected) std::cout << g.summary;
//
// Thread-safety: pure function.
#include <map>
#include <string>
#include <vector>

#include "diagnose/gap/covariate_trend.h"
#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

struct GapOptions {
  double significance = 0.01;  // objectives::limits::kSignificance
  bool IsValid(std::string* error) const;
};

struct ObservableChi2 {
  std::string observable;
  double chi2 = 0;
  int count = 0;
};

struct GapReport {
  int n = 0;  // observations
  int fitted_parameters = 0;
  int dof = 0;  // n − p (at least 1)
  double chi2 = 0;
  double chi2_per_dof = 0;
  double p_value = 1;        // P(χ²_dof > chi2)
  double critical_chi2 = 0;  // the chi2 at which p = significance
  bool gap_detected = false;
  double outlier_threshold = 0;  // |r| above it is flagged
  std::vector<int> outliers;     // indices into the observations
  std::vector<ObservableChi2> by_observable;
  std::vector<CovariateTrend> trends;
  std::string summary;  // one line in words
};

GapReport TestGap(const std::vector<Observation>& observations, int fitted_parameters,
                  const GapOptions& options);

}  // namespace demcal::diagnose
