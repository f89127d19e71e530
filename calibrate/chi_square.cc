#include "calibrate/chi_square.h"

#include <cmath>
#include <limits>

namespace demcal::calibrate {
namespace {

constexpr double kEps = 1e-15;
constexpr int kMaxIterations = 10000;

// P(a, x) by its series, for x < a + 1.
double LowerSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * kEps) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by the continued fraction (modified Lentz), for x >= a + 1.
double UpperFraction(double a, double x) {
  const double tiny = std::numeric_limits<double>::min() / kEps;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1 / d;
    const double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1) < kEps) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double RegularisedUpperGamma(double a, double x) {
  if (x <= 0) return 1.0;
  if (x < a + 1) return 1.0 - LowerSeries(a, x);
  return UpperFraction(a, x);
}

double ChiSquareSurvival(double x, double dof) {
  if (!(x > 0)) return 1.0;
  return RegularisedUpperGamma(0.5 * dof, 0.5 * x);
}

double ChiSquareQuantile(double p, double dof) {
  double lo = 0, hi = dof + 10 * std::sqrt(2 * dof) + 100;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (1 - ChiSquareSurvival(mid, dof) < p) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

double NormalTwoSidedQuantile(double alpha) {
  // |z| > t  <=>  z² > t²: a chi-square with one degree of freedom.
  return std::sqrt(ChiSquareQuantile(1 - alpha, 1));
}

}  // namespace demcal::calibrate
