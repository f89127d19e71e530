#include "objectives/metrics/line_fit.h"

#include <algorithm>
#include <cmath>

namespace demcal::objectives {

LineFit FitLine(const std::vector<double>& xs, const std::vector<double>& ys) {
  LineFit fit;
  const size_t n = xs.size();
  fit.points = static_cast<int>(n);
  if (n < 2 || ys.size() != n) return fit;
  double x_mean = 0, y_mean = 0;
  for (size_t i = 0; i < n; ++i) {
    x_mean += xs[i];
    y_mean += ys[i];
  }
  x_mean /= static_cast<double>(n);
  y_mean /= static_cast<double>(n);
  // Centred sums: stable for coordinates far from the origin (times in s, heights in m).
  double sxx = 0, sxy = 0, syy = 0;
  for (size_t i = 0; i < n; ++i) {
    const double dx = xs[i] - x_mean, dy = ys[i] - y_mean;
    sxx += dx * dx;
    sxy += dx * dy;
    syy += dy * dy;
  }
  if (!(sxx > 0)) return fit;
  fit.ok = true;
  fit.slope = sxy / sxx;
  fit.intercept = y_mean - fit.slope * x_mean;
  const double residual_ss = std::max(0.0, syy - fit.slope * sxy);
  fit.r_squared = syy > 0 ? 1.0 - residual_ss / syy : 1.0;
  if (n >= 3) fit.slope_sem = std::sqrt(residual_ss / static_cast<double>(n - 2) / sxx);
  return fit;
}

}  // namespace demcal::objectives
