#include "calibrate/local_crossing.h"

#include <algorithm>
#include <cmath>

#include "calibrate/chi_square.h"
#include "core/math/number_text.h"

namespace demcal::calibrate {
namespace {

struct Point {
  double u, r, w;
};

using core::NumberText;

// The outermost sign change of the sorted points, [*lo, *hi]; false without one.
bool SignChanges(const std::vector<Point>& p, size_t* lo, size_t* hi) {
  bool found = false;
  for (size_t i = 0; i + 1 < p.size(); ++i) {
    if (p[i].r * p[i + 1].r >= 0) continue;
    if (!found) *lo = i;
    *hi = i + 1;
    found = true;
  }
  return found;
}

struct Line {
  double ubar = 0, alpha = 0, beta = 0, sw = 0, sxx = 0, chi_square = 0;
};

// Weighted least squares through p (at least 2 distinct u); false if the u coincide.
bool FitLine(const std::vector<Point>& p, Line* l) {
  double swu = 0, swr = 0;
  for (const Point& q : p) l->sw += q.w, swu += q.w * q.u, swr += q.w * q.r;
  l->ubar = swu / l->sw, l->alpha = swr / l->sw;
  double sxr = 0;
  for (const Point& q : p) {
    const double d = q.u - l->ubar;
    l->sxx += q.w * d * d, sxr += q.w * d * q.r;
  }
  if (!(l->sxx > 0)) return false;
  l->beta = sxr / l->sxx;
  for (const Point& q : p) {
    const double e = q.r - l->alpha - l->beta * (q.u - l->ubar);
    l->chi_square += q.w * e * e;
  }
  return true;
}

}  // namespace

LocalCrossing FitLocalCrossing(const std::vector<Sample>& samples, double noise_floor) {
  LocalCrossing c;
  std::vector<Point> p;
  for (const Sample& s : samples) {
    const TrialResult& t = s.trial;
    if (!t.ok || s.unit.size() != 1 || t.residuals.size() != 1 || t.noise.size() != 1) continue;
    if (!std::isfinite(s.unit[0]) || !std::isfinite(t.residuals[0]) || !std::isfinite(t.noise[0]))
      continue;
    p.push_back({s.unit[0], t.residuals[0], 1 / (t.noise[0] * t.noise[0] + noise_floor * noise_floor)});
  }
  std::stable_sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.u < b.u; });
  size_t lo = 0, hi = 0;
  if (!SignChanges(p, &lo, &hi)) {
    c.message = "no two neighbouring candidates lie on either side of the measurement";
    return c;
  }
  // Drop the farthest outside [lo, hi] while the line misfits.
  const double middle = 0.5 * (p[lo].u + p[hi].u);
  const double span_lo = p[lo].u, span_hi = p[hi].u;
  Line line;
  while (true) {
    c.points = static_cast<int>(p.size());
    c.window_min = p.front().u, c.window_max = p.back().u;
    if (c.points < 3) {
      c.message = "fewer than 3 candidates around the crossing (a line through 2 cannot be tested)";
      return c;
    }
    line = Line{};
    if (!FitLine(p, &line)) {
      c.message = "the candidates around the crossing share one parameter value";
      return c;
    }
    c.chi_square = line.chi_square, c.dof = c.points - 2;
    const double adequacy = ChiSquareSurvival(c.chi_square, c.dof);
    if (adequacy >= kAdequacyLevel) break;
    const bool front = p.front().u < span_lo, back = p.back().u > span_hi;
    if ((!front && !back) || p.size() == 3) {
      c.message = "a straight line misfits the " + std::to_string(c.points) +
                  " candidates around the crossing (chi-square " + NumberText(c.chi_square, 3) +
                  " on " + std::to_string(c.dof) + " dof, p " + NumberText(adequacy, 3) +
                  " < 0.01): the observable jumps or bends there";
      return c;
    }
    if (front && (!back || middle - p.front().u > p.back().u - middle)) p.erase(p.begin());
    else p.pop_back();
  }
  const double scale = std::max(1.0, c.chi_square / c.dof);
  const double var_alpha = scale / line.sw, var_beta = scale / line.sxx;
  c.slope = line.beta, c.slope_sigma = std::sqrt(var_beta);
  if (std::abs(c.slope) < kSlopeZ * c.slope_sigma) {
    c.message = "the slope through the " + std::to_string(c.points) +
                " candidates around the crossing is not resolved (|slope| " +
                NumberText(std::abs(c.slope) / c.slope_sigma, 3) + " of its standard errors, below 2)";
    return c;
  }
  c.unit = line.ubar - line.alpha / line.beta;
  if (c.unit < c.window_min || c.unit > c.window_max) {
    c.message = "the line crosses the measurement outside the candidates around the crossing";
    return c;
  }
  const double d = c.unit - line.ubar;
  c.residual_sigma = std::sqrt(var_alpha + d * d * var_beta);
  // The crossing moves with the line and with the measurement (unit variance, standardised).
  c.unit_sigma = std::sqrt(1 + c.residual_sigma * c.residual_sigma) / std::abs(c.slope);
  c.fitted = true;
  c.matched = c.residual_sigma <= kMatchNoise;
  c.message = std::string(c.matched ? "matched within noise by" : "estimated by") +
              " a straight line through the " + std::to_string(c.points) +
              " candidates around the crossing (chi-square " + NumberText(c.chi_square, 3) + " on " +
              std::to_string(c.dof) + " dof); its standard error at the crossing is " +
              NumberText(c.residual_sigma, 3) + " measurement uncertainties" +
              (c.matched ? "" : ", coarser than the measurement: more runs near the crossing "
                                "would settle it");
  return c;
}

}  // namespace demcal::calibrate
