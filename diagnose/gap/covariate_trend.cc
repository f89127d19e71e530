#include "diagnose/gap/covariate_trend.h"

#include <cmath>
#include <algorithm>
#include <map>
#include <set>

#include "calibrate/chi_square.h"

namespace demcal::diagnose {

using calibrate::ChiSquareSurvival;
namespace {

// Slope of r on x: var(slope) = s² / Σ(x − x̄)² with s² the scatter about the line, never
// below 1 (the unit variance r has under "no gap"; larger when the misfit varies beyond noise).
bool Slope(const std::vector<double>& x, const std::vector<double>& r, CovariateTrend* out) {
  const double n = static_cast<double>(x.size());
  double mx = 0, mr = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += x[i] / n, mr += r[i] / n;
  double sxx = 0, sxr = 0;
  for (size_t i = 0; i < x.size(); ++i) sxx += (x[i] - mx) * (x[i] - mx), sxr += (x[i] - mx) * (r[i] - mr);
  if (!(sxx > 0)) return false;
  out->points = static_cast<int>(x.size());
  out->slope = sxr / sxx;
  double scatter = 0;
  for (size_t i = 0; i < x.size(); ++i) scatter += std::pow(r[i] - mr - out->slope * (x[i] - mx), 2);
  const double s2 = x.size() > 2 ? std::max(1.0, scatter / (n - 2)) : 1.0;
  out->slope_sigma = std::sqrt(s2 / sxx);
  const double z = out->slope / out->slope_sigma;
  out->p_value = ChiSquareSurvival(z * z, 1);
  return true;
}

// "all": every observable together, each centred on its own mean residual along this
// covariate (a common trend, not the observables' different offsets).
void AddTrend(const std::vector<Observation>& obs, const std::string& column, const std::string& observable,
              double significance, std::vector<CovariateTrend>* out) {
  std::vector<double> x, r;
  std::vector<std::string> kinds;
  std::set<double> distinct;
  for (const Observation& o : obs) {
    double value = 0;
    if (observable != "all" && o.observable != observable) continue;
    if (!calibrate::ConditionNumber(o.condition, column, &value)) continue;
    x.push_back(value);
    r.push_back(o.Residual());
    kinds.push_back(o.observable);
    distinct.insert(value);
  }
  std::map<std::string, std::pair<double, int>> mean;
  for (size_t i = 0; i < r.size(); ++i) mean[kinds[i]].first += r[i], ++mean[kinds[i]].second;
  std::map<std::string, std::set<double>> levels;
  for (size_t i = 0; i < x.size(); ++i) levels[kinds[i]].insert(x[i]);
  std::vector<double> xs, rs;
  for (size_t i = 0; i < r.size(); ++i) {
    if (levels[kinds[i]].size() < 2) continue;  // one level: says nothing about a trend
    xs.push_back(x[i]);
    rs.push_back(r[i] - mean[kinds[i]].first / mean[kinds[i]].second);
  }
  x = xs, r = rs;
  if (x.size() < 3 || distinct.size() < 2) return;
  CovariateTrend t{column, observable};
  if (!Slope(x, r, &t)) return;
  t.significant = t.p_value < significance;
  out->push_back(t);
}

}  // namespace

std::vector<CovariateTrend> FindTrends(const std::vector<Observation>& observations, double significance) {
  std::set<std::string> columns, observables;
  for (const Observation& o : observations) {
    observables.insert(o.observable);
    for (const auto& [column, cell] : o.condition) {
      double ignored = 0;
      if (calibrate::ParseConditionNumber(cell, &ignored)) columns.insert(column);
    }
  }
  std::vector<CovariateTrend> trends;
  for (const std::string& column : columns) {
    AddTrend(observations, column, "all", significance, &trends);
    for (const std::string& observable : observables)
      AddTrend(observations, column, observable, significance, &trends);
  }
  return trends;
}

}  // namespace demcal::diagnose
