#include "calibrate/parameter_covariance.h"

#include <cmath>
#include <limits>

#include "calibrate/jacobian_svd.h"
#include "core/math/number_text.h"

namespace demcal::calibrate {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kUniformSigma = 0.28867513459481287;  // 1/sqrt(12): σ of U(0, 1)
constexpr double kNullComponent = 1e-6;

// Fills σ, identifiability, SI covariance and correlation from a unit covariance and the set of
// parameters with no information (σ = ∞).
ParameterCovariance Finish(const Eigen::MatrixXd& unit, const std::vector<bool>& undetermined,
                           const std::vector<double>& scale) {
  const Eigen::Index n = unit.rows();
  ParameterCovariance c;
  c.covariance = Eigen::MatrixXd::Constant(n, n, kNaN);
  c.correlation = Eigen::MatrixXd::Constant(n, n, kNaN);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double su = undetermined[k] ? kInf : std::sqrt(std::max(unit(k, k), 0.0));
    c.sigma_unit.push_back(su);
    c.sigma.push_back(su * std::abs(scale[k]));
    c.identifiable.push_back(std::isfinite(su) && su <= kUniformSigma);
  }
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b) {
      if (undetermined[a] || undetermined[b]) continue;
      c.covariance(a, b) = unit(a, b) * scale[a] * scale[b];
      const double d = c.sigma_unit[a] * c.sigma_unit[b];
      if (d > 0) c.correlation(a, b) = unit(a, b) / d;
    }
  return c;
}

}  // namespace

std::vector<double> SiPerUnit(const ParameterSpace& space, const std::vector<double>& unit) {
  const std::vector<double> values = space.FromUnit(unit);
  std::vector<double> scale;
  for (size_t k = 0; k < space.parameters.size(); ++k) {
    const Parameter& p = space.parameters[k];
    scale.push_back(p.log_scale ? values[k] * std::log(p.upper / p.lower) : p.upper - p.lower);
  }
  return scale;
}

ParameterCovariance CovarianceFromJacobian(const Eigen::MatrixXd& jacobian,
                                           const std::vector<double>& si_per_unit,
                                           double noise_floor) {
  const JacobianSvd svd = DecomposeJacobian(jacobian, noise_floor);
  const Eigen::Index n = jacobian.cols();
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, n);
  std::vector<bool> undetermined(n, false);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd v = svd.vectors.col(i);
    if (svd.Null(static_cast<int>(i))) {
      for (Eigen::Index k = 0; k < n; ++k)
        if (std::abs(v(k)) > kNullComponent) undetermined[k] = true;
    } else {
      unit += v * v.transpose() / (svd.values(i) * svd.values(i));
    }
  }
  ParameterCovariance c = Finish(unit, undetermined, si_per_unit);
  c.rank = svd.rank;
  c.note = svd.rank == n ? "(J^T J)^-1 of the standardised sensitivity matrix"
                         : "J is rank-deficient (rank " + std::to_string(svd.rank) + " of " +
                               std::to_string(n) +
                               (noise_floor > 0 ? " above the noise floor " +
                                                      core::NumberText(noise_floor) +
                                                      " of its entries' standard errors"
                                                : std::string()) +
                               "): parameters along the unresolved directions have no "
                               "finite sigma";
  return c;
}

ParameterCovariance CovarianceFromUnit(const Eigen::MatrixXd& covariance_unit,
                                       const std::vector<double>& si_per_unit) {
  const Eigen::Index n = covariance_unit.rows();
  std::vector<bool> undetermined(n, false);
  for (Eigen::Index k = 0; k < n; ++k) undetermined[k] = !std::isfinite(covariance_unit(k, k));
  ParameterCovariance c = Finish(covariance_unit, undetermined, si_per_unit);
  c.rank = static_cast<int>(n);
  c.note = "ceres::Covariance";
  return c;
}

}  // namespace demcal::calibrate
