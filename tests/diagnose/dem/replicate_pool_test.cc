#include "diagnose/dem/replicate_pool.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace demcal::diagnose {

TEST_CASE("replicate pool: the within-run correlation of two observables", "[unit]") {
  // Target 0 and 1 read one run (angle and height of one heap), correlated +0.7 run to run,
  // about a mean that moves from evaluation to evaluation; target 2 another run. Two replicates
  // per evaluation: each gives one degree of freedom.
  std::mt19937 rng(3);
  std::normal_distribution<double> z(0, 1);
  const double rho = 0.7;
  ReplicatePool pool(3);
  auto evaluate = [&](int evaluations) {
    for (int e = 0; e < evaluations; ++e) {
      const double shift = 5 * z(rng);  // the parameters move the means, not the scatter
      std::vector<std::vector<double>> v(3);
      for (int j = 0; j < 2; ++j) {
        const double a = z(rng), b = rho * a + std::sqrt(1 - rho * rho) * z(rng);
        v[0].push_back(20 + shift + 2 * a);
        v[1].push_back(0.01 + 0.001 * b);
        v[2].push_back(3 + z(rng));
      }
      pool.Add(v, {0, 0, 1});
    }
  };
  evaluate(kMinCorrelationDof - 1);
  CHECK(pool.CorrelationDof(0, 1) == kMinCorrelationDof - 1);
  CHECK(pool.Correlation(0, 1) == 0.0);  // too few pairs: not used
  evaluate(400);
  CHECK(pool.Correlation(0, 1) == Approx(rho).margin(0.1));
  CHECK(pool.Correlation(1, 0) == pool.Correlation(0, 1));
  CHECK(pool.Correlation(0, 2) == 0.0);  // another run
  CHECK(pool.CorrelationDof(0, 2) == 0);
  CHECK(pool.Spread(0) == Approx(2).margin(0.2));
  CHECK(pool.Spread(1) == Approx(0.001).margin(0.0001));
  CHECK(pool.Dof(0) == 400 + kMinCorrelationDof - 1);
}

TEST_CASE("replicate pool: a run without a value leaves that replicate out", "[unit]") {
  ReplicatePool pool(2);
  CHECK(pool.Spread(0) < 0);  // nothing pooled yet
  pool.Add({{1.0, NAN, 3.0}, {2.0, 5.0, 4.0}}, {0, 0});
  CHECK(pool.Dof(0) == 1);  // two values
  CHECK(pool.Spread(0) == Approx(std::sqrt(2.0)));
  CHECK(pool.Dof(1) == 2);
  CHECK(pool.CorrelationDof(0, 1) == 1);  // replicates 0 and 2 only
}

}  // namespace demcal::diagnose
