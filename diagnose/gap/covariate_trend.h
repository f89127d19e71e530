#pragma once
// CovariateTrend: whether the standardised residuals of one observable trend along a numeric
// condition column (coating level, size, ...): the least-squares slope of r against the
// covariate, its standard error (from the scatter about the line, never below the unit
// variance r has under "no gap") and the two-sided p-value of slope = 0; "all" pools every
// observable, each centred on its own mean (observables measured at one level only are left out). A significant slope says where a missing effect lives: a residual that
// grows with the coating level points at adhesion, one that does not trend at all at an effect
// present in every condition. Needs at least 3 observations at 2 or more distinct values.
//
//   std::vector<CovariateTrend> t = FindTrends(observations, 0.01);
//
// Thread-safety: pure function.
#include <string>
#include <vector>

#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

struct CovariateTrend {
  std::string covariate;   // condition column
  std::string observable;  // or "all" for every observable together
  int points = 0;
  double slope = 0;        // standardised residual per unit of the covariate
  double slope_sigma = 0;
  double p_value = 1;
  bool significant = false;  // p < significance
};

std::vector<CovariateTrend> FindTrends(const std::vector<Observation>& observations,
                                       double significance);

}  // namespace demcal::diagnose
