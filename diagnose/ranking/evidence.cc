#include "diagnose/ranking/evidence.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "calibrate/chi_square.h"
#include "diagnose/ranking/discrepancy_floor.h"
#include "diagnose/ranking/f_distribution.h"

namespace demcal::diagnose {

using calibrate::ChiSquareSurvival;

Evidence EvidenceOf(double chi2_base, double chi2_effect, int k, int n, double significance) {
  Evidence e;
  e.delta_chi2 = chi2_base - chi2_effect;
  e.lr_p_value = ChiSquareSurvival(std::max(0.0, e.delta_chi2), k);
  e.delta_bic = chi2_effect - chi2_base + k * std::log(static_cast<double>(std::max(n, 1)));
  e.significant = e.lr_p_value < significance && e.delta_bic < 0;
  return e;
}

Evidence EvidenceWithFloor(const Eigen::VectorXd& r_base, const Eigen::VectorXd& r_effect,
                           const Eigen::VectorXd& q, int k, int fitted, double significance) {
  const int n = static_cast<int>(r_base.size());
  const int dof = std::max(1, n - fitted - k);
  Evidence e;
  e.floor = EstimateFloor(r_effect, q, dof);
  e.delta_chi2 = FlooredChi2(r_base, q, e.floor) - FlooredChi2(r_effect, q, e.floor);
  e.lr_p_value = e.floor > 0 ? FSurvival(std::max(0.0, e.delta_chi2) / k, k, dof)
                             : ChiSquareSurvival(std::max(0.0, e.delta_chi2), k);
  e.penalty = k * std::log(static_cast<double>(std::max(n, 1)));
  e.delta_bic = -e.delta_chi2 + e.penalty;
  e.significant = e.lr_p_value < significance && e.delta_bic < 0;
  e.residuals = r_effect;
  e.q = q;
  return e;
}

double BicGap(const Evidence& a, const Evidence& b) {
  if (a.residuals.size() == 0 || a.residuals.size() != b.residuals.size() ||
      a.q.size() != a.residuals.size() || b.q.size() != b.residuals.size())
    return a.delta_bic - b.delta_bic;
  const double phi = std::min(a.floor, b.floor);
  return FlooredChi2(a.residuals, a.q, phi) + a.penalty - FlooredChi2(b.residuals, b.q, phi) -
         b.penalty;
}

double Chi2NoiseSd(const Eigen::VectorXd& r, const Eigen::VectorXd& u, const Eigen::VectorXd& q,
                   double phi, const std::vector<int>& source) {
  // Per source the sum of 2·r_i·w_i·u_i of its rows; a row without one is a source of its own.
  std::map<int, double> shared;
  double var = 0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const double w = 1 / (1 + phi * phi * q(i) * q(i));
    const double term = 2 * r(i) * w * u(i);
    const int s = i < static_cast<Eigen::Index>(source.size()) ? source[i] : -1;
    if (s < 0) var += term * term;
    else shared[s] += term;
  }
  for (const auto& [s, sum] : shared) var += sum * sum;
  return std::sqrt(var);
}

double CorrelatedChi2NoiseSd(const Eigen::VectorXd& r, const Eigen::VectorXd& u,
                             const Eigen::VectorXd& q, double phi,
                             const Eigen::MatrixXd& correlation) {
  Eigen::VectorXd a(r.size());
  for (Eigen::Index i = 0; i < r.size(); ++i)
    a(i) = 2 * r(i) * u(i) / (1 + phi * phi * q(i) * q(i));
  if (correlation.rows() != r.size() || correlation.cols() != r.size()) return a.norm();
  return std::sqrt(std::max(0.0, a.dot(correlation * a)));
}

Eigen::MatrixXd ErrorCorrelation(const std::vector<int>& source,
                                 const std::vector<std::vector<double>>& rows, Eigen::Index n) {
  Eigen::MatrixXd c = Eigen::MatrixXd::Identity(n, n);
  const bool given = static_cast<Eigen::Index>(rows.size()) == n &&
                     std::all_of(rows.begin(), rows.end(), [n](const std::vector<double>& row) {
                       return static_cast<Eigen::Index>(row.size()) == n;
                     });
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      if (i == j) continue;
      if (given) {
        c(i, j) = rows[i][j];
      } else {
        const int si = i < static_cast<Eigen::Index>(source.size()) ? source[i] : -1;
        const int sj = j < static_cast<Eigen::Index>(source.size()) ? source[j] : -1;
        c(i, j) = si >= 0 && si == sj ? 1.0 : 0.0;
      }
    }
  return c;
}

double IndistinctWithin(const Evidence& a, const Evidence& b) {
  const double sd = std::hypot(a.chi2_noise_sd, b.chi2_noise_sd);
  return std::max(kBicIndistinct, kNoiseSds * sd);
}

bool ToldApart(const Evidence& a, const Evidence& b) {
  return std::fabs(BicGap(a, b)) >= IndistinctWithin(a, b);
}

}  // namespace demcal::diagnose
