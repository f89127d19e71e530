#include "diagnose/loop/base_step.h"

#include <Eigen/Dense>
#include <algorithm>

#include "calibrate/jacobian_svd.h"

namespace demcal::diagnose {
namespace {

// Least squares J Δ ≈ −r over the singular directions above the floor (truncated SVD).
Eigen::VectorXd TruncatedSolve(const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                               double noise_floor, int* rank) {
  *rank = 0;
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(J.cols());
  if (J.cols() == 0 || J.rows() == 0) return delta;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    if (s(k) <= noise_floor || s(k) <= calibrate::kRankTolerance * s(0)) continue;
    delta -= svd.matrixV().col(k) * (svd.matrixU().col(k).dot(r) / s(k));
    ++*rank;
  }
  return delta;
}

}  // namespace

BaseStep LinearisedBaseStep(const std::vector<Observation>& at, const std::vector<double>& unit,
                            const std::vector<std::vector<double>>& jacobian,
                            const std::vector<std::vector<double>>& jacobian_sigma) {
  BaseStep step;
  step.unit = unit;
  const int n = static_cast<int>(at.size()), p = static_cast<int>(unit.size());
  Eigen::VectorXd r(n);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, p), J_sigma = Eigen::MatrixXd::Zero(n, p);
  for (int i = 0; i < n; ++i) {
    const double sigma = at[i].Sigma();
    r(i) = at[i].Residual();
    step.max_noise_per_sigma = std::max(step.max_noise_per_sigma, at[i].sem / sigma);
    for (int j = 0; j < p; ++j) {
      if (i < static_cast<int>(jacobian.size()) && j < static_cast<int>(jacobian[i].size()))
        J(i, j) = jacobian[i][j] / sigma;
      if (i < static_cast<int>(jacobian_sigma.size()) &&
          j < static_cast<int>(jacobian_sigma[i].size()))
        J_sigma(i, j) = jacobian_sigma[i][j] / sigma;
    }
  }
  step.chi2_now = step.chi2_predicted = r.squaredNorm();
  if (p == 0 || n == 0) return step;
  // Active set: a coordinate the step pushes out of the cube is fixed on that bound, and the
  // others are solved again against the residuals that move leaves.
  std::vector<bool> fixed(p, false);
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(p);
  for (int pass = 0; pass <= p; ++pass) {
    std::vector<int> free;
    Eigen::VectorXd r_fixed = r;
    for (int j = 0; j < p; ++j) {
      if (fixed[j]) r_fixed += J.col(j) * delta(j);
      else free.push_back(j);
    }
    Eigen::MatrixXd J_free(n, free.size()), S_free(n, free.size());
    for (size_t k = 0; k < free.size(); ++k)
      J_free.col(k) = J.col(free[k]), S_free.col(k) = J_sigma.col(free[k]);
    const Eigen::VectorXd d =
        TruncatedSolve(J_free, r_fixed, calibrate::JacobianNoiseFloor(S_free), &step.rank);
    bool clamped = false;
    for (size_t k = 0; k < free.size(); ++k) {
      const int j = free[k];
      delta(j) = d(k);
      const double u = unit[j] + delta(j);
      if (u < 0 || u > 1) {
        delta(j) = std::clamp(u, 0.0, 1.0) - unit[j];
        fixed[j] = clamped = true;
      }
    }
    if (!clamped) break;
  }
  for (int j = 0; j < p; ++j) step.unit[j] = std::clamp(unit[j] + delta(j), 0.0, 1.0);
  step.chi2_predicted = (r + J * delta).squaredNorm();
  step.ok = delta.lpNorm<Eigen::Infinity>() > 0;
  return step;
}

std::vector<double> PartWay(const std::vector<double>& from, const std::vector<double>& to,
                            double fraction) {
  std::vector<double> u = from;
  for (size_t j = 0; j < u.size() && j < to.size(); ++j) u[j] += fraction * (to[j] - from[j]);
  return u;
}

}  // namespace demcal::diagnose
