#include "diagnose/gap/gap_significance.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "calibrate/chi_square.h"
#include "objectives/common/input_limits.h"

namespace demcal::diagnose {

using calibrate::ChiSquareQuantile;
using calibrate::ChiSquareSurvival;
using calibrate::NormalTwoSidedQuantile;

bool GapOptions::IsValid(std::string* error) const {
  if (objectives::limits::kSignificance.Contains(significance)) return true;
  *error = "significance must be in " + objectives::limits::kSignificance.Text() + ", got " +
           std::to_string(significance);
  return false;
}

namespace {

std::string Summary(const GapReport& g, double significance) {
  std::ostringstream s;
  s.precision(3);
  s << "chi2 = " << g.chi2 << " on " << g.dof << " dof (chi2/dof = " << g.chi2_per_dof
    << ", p = " << g.p_value << "): " << (g.gap_detected ? "a gap beyond noise" : "within noise");
  if (g.gap_detected && !g.by_observable.empty()) {
    const auto worst = std::max_element(
        g.by_observable.begin(), g.by_observable.end(),
        [](const ObservableChi2& a, const ObservableChi2& b) { return a.chi2 < b.chi2; });
    s << ", mostly in " << worst->observable << " (chi2 " << worst->chi2 << " over " << worst->count
      << ")";
  }
  for (const CovariateTrend& t : g.trends)
    if (t.significant && t.observable == "all")
      s << "; residuals trend along " << t.covariate << " (slope " << t.slope << " +- "
        << t.slope_sigma << ")";
  // Where a gap lives when one observable carries a trend the pooled one dilutes (the heap
  // height alone growing with the coating): per-observable trends at the significance over all
  // of them (Bonferroni), so that a model that fits names none with probability ≥ 1 − α.
  int per_observable = 0;
  for (const CovariateTrend& t : g.trends) per_observable += t.observable != "all";
  for (const CovariateTrend& t : g.trends)
    if (g.gap_detected && t.observable != "all" &&
        t.p_value < significance / std::max(1, per_observable))
      s << "; " << t.observable << " residuals trend along " << t.covariate << " (slope " << t.slope
        << " +- " << t.slope_sigma << ")";
  return s.str();
}

}  // namespace

GapReport TestGap(const std::vector<Observation>& observations, int fitted_parameters,
                  const GapOptions& options) {
  GapReport g;
  g.n = static_cast<int>(observations.size());
  g.fitted_parameters = fitted_parameters;
  g.dof = std::max(1, g.n - fitted_parameters);
  std::map<std::string, ObservableChi2> by;
  g.outlier_threshold = NormalTwoSidedQuantile(options.significance / std::max(1, g.n));
  for (int i = 0; i < g.n; ++i) {
    const double r = observations[i].Residual();
    g.chi2 += r * r;
    ObservableChi2& b = by[observations[i].observable];
    b.observable = observations[i].observable;
    b.chi2 += r * r;
    ++b.count;
    if (std::fabs(r) > g.outlier_threshold) g.outliers.push_back(i);
  }
  for (const auto& [name, b] : by) g.by_observable.push_back(b);
  g.chi2_per_dof = g.chi2 / g.dof;
  g.p_value = ChiSquareSurvival(g.chi2, g.dof);
  g.critical_chi2 = ChiSquareQuantile(1 - options.significance, g.dof);
  g.trends = FindTrends(observations, options.significance);
  // Two tests share the significance (Bonferroni): the chi-square at α/2 and the pooled residual
  // trend along each of the C numeric covariates at α/(2C). A trend is a gap the chi-square
  // dilutes over every observation (an effect that grows with the coating level while the fit
  // splits the difference).
  int covariates = 0;
  for (const CovariateTrend& t : g.trends) covariates += t.observable == "all";
  const double alpha = covariates > 0 ? options.significance / 2 : options.significance;
  g.gap_detected = g.p_value < alpha;
  for (const CovariateTrend& t : g.trends)
    if (t.observable == "all" && t.p_value < alpha / covariates) g.gap_detected = true;
  g.summary = Summary(g, options.significance);
  return g;
}

}  // namespace demcal::diagnose
