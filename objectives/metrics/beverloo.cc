#include "objectives/metrics/beverloo.h"
#include "core/math/number_text.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace demcal::objectives {

double BeverlooMassFlow(double C, double k, double orifice_diameter_m, double bulk_density_kg_m3,
                        double particle_diameter_m, double g_m_s2) {
  const double open = orifice_diameter_m - k * particle_diameter_m;
  if (!(open > 0)) return 0;
  return C * bulk_density_kg_m3 * std::sqrt(g_m_s2) * std::pow(open, 2.5);
}

namespace {

constexpr double kMinOpenWidth = 0.01;  // of a grain diameter, see FitBeverloo

struct Material {
  double density, diameter, g;
};

// For a given k: the C minimising the relative squared residuals, Σ((C f − W)/W)² with
// f = W(C = 1), is C = Σ(f/W) / Σ(f/W)²; returns the rms relative residual.
double BestC(const std::vector<BeverlooPoint>& points, const Material& m, double k, double* C) {
  double a = 0, b = 0;
  std::vector<double> ratio;
  for (const BeverlooPoint& p : points) {
    const double q =
        BeverlooMassFlow(1, k, p.orifice_diameter_m, m.density, m.diameter, m.g) / p.mass_flow_kg_s;
    ratio.push_back(q);
    a += q;
    b += q * q;
  }
  *C = b > 0 ? a / b : 0;
  double ss = 0;
  for (double q : ratio) ss += (*C * q - 1) * (*C * q - 1);
  return std::sqrt(ss / static_cast<double>(points.size()));
}

// Golden-section search for the minimum of the residual over [lo, hi], after a coarse scan so a
// non-unimodal residual still lands in the right valley.
double MinimiseOverK(const std::vector<BeverlooPoint>& points, const Material& m, double lo,
                     double hi) {
  auto residual = [&](double k) {
    double c;
    return BestC(points, m, k, &c);
  };
  constexpr int kScan = 200;
  const double step = (hi - lo) / kScan;
  int best = 0;
  for (int i = 1; i <= kScan; ++i)
    if (residual(lo + i * step) < residual(lo + best * step)) best = i;
  double a = lo + std::max(0, best - 1) * step, b = lo + std::min(kScan, best + 1) * step;
  const double inv_phi = (std::sqrt(5.0) - 1) / 2;
  double x1 = b - inv_phi * (b - a), x2 = a + inv_phi * (b - a);
  double f1 = residual(x1), f2 = residual(x2);
  while (b - a > 1e-12 * (1 + std::abs(b))) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - inv_phi * (b - a), f1 = residual(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + inv_phi * (b - a), f2 = residual(x2);
    }
  }
  return (a + b) / 2;
}

std::string InputProblem(const std::vector<BeverlooPoint>& points, const Material& m) {
  if (!(m.density > 0 && m.diameter > 0 && m.g > 0 && std::isfinite(m.density) &&
        std::isfinite(m.diameter) && std::isfinite(m.g)))
    return "bulk density, particle diameter and g must be positive and finite";
  std::set<double> sizes;
  for (const BeverlooPoint& p : points) {
    if (!(p.mass_flow_kg_s > 0) || !std::isfinite(p.mass_flow_kg_s))
      return "every mass flow must be positive and finite";
    if (!(p.orifice_diameter_m > m.diameter) || !std::isfinite(p.orifice_diameter_m))
      return "every orifice must be wider than a particle (D > d)";
    sizes.insert(p.orifice_diameter_m);
  }
  if (sizes.size() < 3)
    return "need at least 3 different orifice sizes (have " + std::to_string(sizes.size()) + ")";
  return "";
}

}  // namespace

BeverlooFit FitBeverloo(const std::vector<BeverlooPoint>& points, double bulk_density_kg_m3,
                        double particle_diameter_m, double g_m_s2) {
  BeverlooFit fit;
  const Material m{bulk_density_kg_m3, particle_diameter_m, g_m_s2};
  fit.message = InputProblem(points, m);
  if (!fit.message.empty()) return fit;
  double d_min = INFINITY;
  for (const BeverlooPoint& p : points) d_min = std::min(d_min, p.orifice_diameter_m);
  const double k_limit = d_min / particle_diameter_m;
  fit.k = MinimiseOverK(points, m, 0, k_limit);
  fit.rms_relative_residual = BestC(points, m, fit.k, &fit.C);
  // The search cannot reach D = k d itself; an open width below 1% of a grain there means the data
  // ask for a blocked smallest orifice.
  if (d_min - fit.k * particle_diameter_m < kMinOpenWidth * particle_diameter_m) {
    fit.message = "the best k = " + core::NumberText(fit.k) +
                  " nearly closes the smallest orifice (min D/d = " + core::NumberText(k_limit) +
                  "): the data ask for D <= k d";
    return fit;
  }
  fit.ok = true;
  fit.message = "ok";
  return fit;
}

}  // namespace demcal::objectives
