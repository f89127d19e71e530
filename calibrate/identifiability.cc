#include "calibrate/identifiability.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "calibrate/jacobian_svd.h"

namespace demcal::calibrate {
namespace {

constexpr double kInvolved = 0.1;

std::string Describe(const UndeterminedDirection& d, const std::vector<std::string>& names) {
  const std::vector<double>& v = d.unit_direction;
  const double top = *std::max_element(
      v.begin(), v.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  std::vector<size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return std::abs(v[a]) > std::abs(v[b]); });
  std::vector<size_t> involved;
  for (size_t k : order)
    if (std::abs(v[k]) >= kInvolved * std::abs(top)) involved.push_back(k);
  std::ostringstream out;
  out.precision(2);
  out << std::showpos;
  auto names_of = [&] {
    std::string s;
    for (size_t i = 0; i < involved.size(); ++i)
      s += (i ? (i + 1 == involved.size() ? " and " : ", ") : "") + names[involved[i]];
    return s;
  };
  if (involved.size() == 1) {
    out << std::noshowpos << names[involved[0]] << " is not determined: the targets hardly change "
        << "with it";
  } else {
    out << std::noshowpos << names_of() << " trade off: " << std::showpos;
    for (size_t i = 0; i < involved.size(); ++i)
      out << (i ? " ~ " : "") << std::fixed << v[involved[i]] / top << " " << names[involved[i]];
    out << std::defaultfloat << " (in fractions of each parameter's range; in SI";
    out.precision(3);
    for (size_t i = 0; i < involved.size(); ++i)
      out << (i ? " with " : " ") << d.si_direction[involved[i]] / top << " " << names[involved[i]];
    out << ") leaves the targets unchanged";
  }
  out << std::noshowpos;
  out.precision(3);
  if (std::isfinite(d.sigma_unit))
    out << " within noise (the data fix it only to +-" << d.sigma_unit << " of the range)";
  else if (d.singular_value > 0)
    out << " as far as the runs can tell (its sensitivity, " << d.singular_value
        << ", is within the noise of the estimated sensitivities: more replicates per candidate "
           "or a target that responds more strongly would resolve it)";
  else
    out << " exactly (no target sees this combination)";
  return out.str();
}

}  // namespace

IdentifiabilityReport AnalyseIdentifiability(const Eigen::MatrixXd& jacobian,
                                             const std::vector<std::string>& names,
                                             const std::vector<double>& si_per_unit,
                                             double noise_floor) {
  IdentifiabilityReport r;
  r.names = names;
  const Eigen::Index n = jacobian.cols();
  if (n == 0) return r;
  const JacobianSvd svd = DecomposeJacobian(jacobian, noise_floor);
  for (Eigen::Index i = 0; i < n; ++i)
    r.singular_values.push_back(svd.values(i) > kRankTolerance * svd.values(0) ? svd.values(i) : 0.0);
  const double s_min = r.singular_values.back();
  r.condition_number =
      s_min > 0 ? r.singular_values.front() / s_min : std::numeric_limits<double>::infinity();
  std::ostringstream summary;
  summary.precision(3);
  summary << "singular values of the standardised sensitivity matrix:";
  for (double s : r.singular_values) summary << " " << s;
  summary << " (condition number " << r.condition_number << "; a combination with singular value"
          << " <= sqrt(12) is undetermined";
  if (noise_floor > 0)
    summary << ", and one <= " << noise_floor
            << ", the noise floor of the sensitivities' own standard errors, is not resolved";
  summary << ")\n";
  for (Eigen::Index i = 0; i < n; ++i) {
    const double s = r.singular_values[i];
    const bool resolved = !svd.Null(static_cast<int>(i));
    if (resolved && s > kUndeterminedSingular) continue;
    UndeterminedDirection d;
    for (Eigen::Index k = 0; k < n; ++k) {
      d.unit_direction.push_back(svd.vectors(k, i));
      d.si_direction.push_back(svd.vectors(k, i) * si_per_unit[k]);
    }
    d.singular_value = s;
    d.sigma_unit = resolved ? 1 / s : std::numeric_limits<double>::infinity();
    d.description = Describe(d, names);
    summary << d.description << "\n";
    r.undetermined.push_back(std::move(d));
  }
  if (r.undetermined.empty()) summary << "every parameter is determined by the targets\n";
  r.summary = summary.str();
  return r;
}

}  // namespace demcal::calibrate
