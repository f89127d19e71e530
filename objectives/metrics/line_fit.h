#pragma once
// LineFit: ordinary least-squares straight line y = intercept + slope·x, shared by the heap-flank
// fit (height vs horizontal distance) and the discharge rate (mass vs time). Plain values; units
// are those of the inputs (slope in [y]/[x]).
//
//   LineFit f = FitLine(xs, ys);
//   if (f.ok) angle = std::atan(std::abs(f.slope));
#include <vector>

namespace demcal::objectives {

struct LineFit {
  bool ok = false;  // false: fewer than 2 points, unequal lengths or all x equal
  double slope = 0;
  double intercept = 0;
  double r_squared = 0;  // 1 when every point lies on the line (also for a constant y)
  double slope_sem = 0;  // standard error of the slope (needs ≥ 3 points; else 0)
  int points = 0;
};

LineFit FitLine(const std::vector<double>& xs, const std::vector<double>& ys);

}  // namespace demcal::objectives
