#include "core/materials/material.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace demcal::core {

double SizeDistribution::MaxDiameter() const {
  switch (kind) {
    case Kind::kFixed: return diameter_m;
    case Kind::kUniform: return max_diameter_m;
    case Kind::kTable: return *std::max_element(table_diameter_m.begin(), table_diameter_m.end());
  }
  return 0;
}

double SizeDistribution::MinDiameter() const {
  switch (kind) {
    case Kind::kFixed: return diameter_m;
    case Kind::kUniform: return min_diameter_m;
    case Kind::kTable: return *std::min_element(table_diameter_m.begin(), table_diameter_m.end());
  }
  return 0;
}

double SizeDistribution::Sample(double u) const {
  switch (kind) {
    case Kind::kFixed: return diameter_m;
    case Kind::kUniform: return min_diameter_m + u * (max_diameter_m - min_diameter_m);
    case Kind::kTable: {
      double cumulative = 0;
      for (size_t k = 0; k < table_diameter_m.size(); ++k) {
        cumulative += table_number_fraction[k];
        if (u < cumulative) return table_diameter_m[k];
      }
      return table_diameter_m.back();
    }
  }
  return 0;
}

double SizeDistribution::MeanVolume() const {
  const double c = std::numbers::pi / 6.0;
  switch (kind) {
    case Kind::kFixed: return c * std::pow(diameter_m, 3);
    case Kind::kUniform: {  // mean of d^3 for d uniform in [a, b]
      const double a = min_diameter_m, b = max_diameter_m;
      if (b == a) return c * a * a * a;
      return c * (std::pow(b, 4) - std::pow(a, 4)) / (4.0 * (b - a));
    }
    case Kind::kTable: {
      double v = 0;
      for (size_t k = 0; k < table_diameter_m.size(); ++k)
        v += table_number_fraction[k] * c * std::pow(table_diameter_m[k], 3);
      return v;
    }
  }
  return 0;
}

}  // namespace demcal::core
