// The χ² noise of rows whose simulation errors are correlated: two observables of one run.
#include <Eigen/Cholesky>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "diagnose/ranking/discrepancy_floor.h"
#include "diagnose/ranking/evidence.h"

namespace demcal::diagnose {
namespace {

// The standard deviation of the floored χ² over 40000 draws of the simulated means, their
// errors u_i·z_i with z ~ N(0, C).
double SampledChi2Sd(const Eigen::VectorXd& r, const Eigen::VectorXd& u, const Eigen::VectorXd& q,
                     double phi, const Eigen::MatrixXd& c, unsigned seed) {
  const Eigen::MatrixXd l = c.llt().matrixL();
  std::mt19937 rng(seed);
  std::normal_distribution<double> z(0, 1);
  const int draws = 40000;
  double sum = 0, sum2 = 0;
  for (int k = 0; k < draws; ++k) {
    Eigen::VectorXd e(r.size());
    for (Eigen::Index i = 0; i < e.size(); ++i) e(i) = z(rng);
    const double chi2 = FlooredChi2(r + u.cwiseProduct(l * e), q, phi);
    sum += chi2, sum2 += chi2 * chi2;
  }
  return std::sqrt(sum2 / draws - (sum / draws) * (sum / draws));
}

}  // namespace

TEST_CASE("evidence: two observables of one run share its noise in the chi2 noise", "[unit]") {
  // A heap (angle, height: errors +0.6 correlated, residuals of one sign) and a funnel
  // (discharge time, mass flow: −0.8, residuals of opposite signs, as a slower funnel gives):
  // in both runs the two terms move together, so rows counted as independent (the sources
  // alone: each row its own) fall short of the sampled noise; the correlated delta method holds.
  const Eigen::VectorXd r = (Eigen::VectorXd(5) << 3, 2.5, 2.8, -3.2, 1).finished();
  const Eigen::VectorXd u = (Eigen::VectorXd(5) << 0.3, 0.25, 0.3, 0.3, 0.2).finished();
  const Eigen::VectorXd q = (Eigen::VectorXd(5) << 1, 1.5, 1, 1, 2).finished();
  Eigen::MatrixXd c = Eigen::MatrixXd::Identity(5, 5);
  c(0, 1) = c(1, 0) = 0.6;
  c(2, 3) = c(3, 2) = -0.8;
  const double phi = 0.5;
  const double sd = SampledChi2Sd(r, u, q, phi, c, 5);
  CHECK(CorrelatedChi2NoiseSd(r, u, q, phi, c) == Approx(sd).epsilon(0.03));
  CHECK(Chi2NoiseSd(r, u, q, phi) < 0.85 * sd);  // the formula before: independent rows
  // Terms of opposite signs in one run: the independent rows overstate the noise.
  Eigen::MatrixXd opposite = c;
  opposite(2, 3) = opposite(3, 2) = 0.8;
  const double sd_opposite = SampledChi2Sd(r, u, q, phi, opposite, 6);
  CHECK(CorrelatedChi2NoiseSd(r, u, q, phi, opposite) == Approx(sd_opposite).epsilon(0.03));
  CHECK(Chi2NoiseSd(r, u, q, phi) > 1.05 * sd_opposite);
}

TEST_CASE("evidence: the error correlation from sources gives the grouped formula", "[unit]") {
  const Eigen::VectorXd r = (Eigen::VectorXd(4) << 3, 2.5, -2, 1).finished();
  const Eigen::VectorXd u = (Eigen::VectorXd(4) << 0.2, 0.2, 0.3, 0.25).finished();
  const Eigen::VectorXd q = Eigen::VectorXd::Ones(4);
  const std::vector<int> source = {4, 4, -1, 2};
  const Eigen::MatrixXd c = ErrorCorrelation(source, {}, 4);
  CHECK(c(0, 1) == 1.0);
  CHECK(c(0, 2) == 0.0);
  CHECK(c(2, 2) == 1.0);
  CHECK(CorrelatedChi2NoiseSd(r, u, q, 0.3, c) == Approx(Chi2NoiseSd(r, u, q, 0.3, source)));
  // Rows given (a prediction's matrix) win over the sources.
  const std::vector<std::vector<double>> rows = {
      {1, 1, 0.5, 0}, {1, 1, 0.5, 0}, {0.5, 0.5, 1, 0}, {0, 0, 0, 1}};
  CHECK(ErrorCorrelation(source, rows, 4)(0, 2) == 0.5);
  // Rows of the wrong length: the sources.
  CHECK(ErrorCorrelation(source, {{1, 0}}, 4)(0, 2) == 0.0);
}

}  // namespace demcal::diagnose
