#include "calibrate/sensitivity_refinement.h"

#include <algorithm>
#include <cmath>

namespace demcal::calibrate {
namespace {

// The finite-difference step rule of optimiser_ceres.cc (see there for why these values).
constexpr double kMinSensitivity = 3.4641016151377544;  // sqrt(12)
constexpr double kSignalToNoise = 4;
constexpr double kMinStep = 0.01;
constexpr double kMaxStep = 0.25;

}  // namespace

double FiniteDifferenceStep(double noise_max) {
  return std::clamp(kSignalToNoise * noise_max / kMinSensitivity, kMinStep, kMaxStep);
}

std::vector<std::vector<double>> RefinementStencil(const std::vector<double>& best_unit,
                                                   double noise_max, int round) {
  const double h = std::min(kMaxStep, std::ldexp(FiniteDifferenceStep(noise_max), round + 1));
  std::vector<std::vector<double>> points;
  for (size_t k = 0; k < best_unit.size(); ++k)
    for (double side : {-1.0, 1.0}) {
      std::vector<double> u = best_unit;
      u[k] += side * h;
      if (u[k] >= 0 && u[k] <= 1) points.push_back(u);
    }
  return points;
}

}  // namespace demcal::calibrate
