#include "diagnose/ranking/linear_refit.h"

#include <catch2/catch.hpp>

namespace demcal::diagnose {

TEST_CASE("linear refit recovers an effect's strength and the base step exactly", "[unit]") {
  Eigen::MatrixXd J(4, 1), S(4, 1);
  J << 1, 2, 0, 1;
  S << 0, 1, 3, -1;
  const double t = 0.4, d = -0.1;
  const Eigen::VectorXd r0 = -(J.col(0) * d + S.col(0) * t);
  const LinearRefitResult f = LinearRefit(r0, J, S, {0}, {1}, {-0.5}, {0.5});
  CHECK(f.t(0) == Approx(t).epsilon(1e-10));
  CHECK(f.delta(0) == Approx(d).epsilon(1e-10));
  CHECK(f.chi2 == Approx(0).margin(1e-20));
  CHECK(SignatureMatch(r0, J, S.col(0)) == Approx(1).epsilon(1e-10));
}

TEST_CASE("linear refit keeps the effect in its bounds; a redundant effect gains nothing", "[unit]") {
  Eigen::MatrixXd J(3, 1), S(3, 1);
  J << 1, 1, 0;
  S << 0, 0, 1;
  Eigen::VectorXd r0(3);
  r0 << 0, 0, 2;  // asks for t = -2, outside [0, 1]
  const LinearRefitResult f = LinearRefit(r0, J, S, {0}, {1}, {-1}, {1});
  CHECK(f.t(0) == 0);
  CHECK(f.chi2 == Approx(4));
  // The control: a signature that is a multiple of J's column.
  Eigen::MatrixXd C = 0.3 * J;
  r0 << 1, -1, 0.5;
  const double base = r0.squaredNorm();
  const LinearRefitResult c = LinearRefit(r0, J, C, {-1}, {1}, {-1}, {1});
  const LinearRefitResult none = LinearRefit(r0, J, Eigen::MatrixXd::Zero(3, 1), {-1}, {1}, {-1}, {1});
  CHECK(c.chi2 == Approx(none.chi2).epsilon(1e-10));
  CHECK(c.chi2 <= base);
  CHECK(SignatureMatch(r0, J, C.col(0)) == 0);
}

}  // namespace demcal::diagnose
