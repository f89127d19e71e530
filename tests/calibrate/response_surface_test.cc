// The local response surface: sensitivities recovered from scattered noisy candidates, with
// honest standard errors; quadratic when there are enough points.
#include "calibrate/response_surface.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "analytic_models.h"
#include "core/math/random.h"

using namespace demcal::calibrate;
using demcal::calibrate::testing::Normal;

namespace {

// Samples around `centre` (±0.15) of residuals r = f(u) + noise·z, z drawn per sample.
std::vector<Sample> Cloud(int count, const std::vector<double>& centre, double noise, uint64_t seed,
                          const std::function<std::vector<double>(const std::vector<double>&)>& f) {
  demcal::core::Rng rng(seed);
  std::vector<Sample> out;
  for (int i = 0; i < count; ++i) {
    std::vector<double> u{centre[0] + rng.Uniform(-0.15, 0.15),
                          centre[1] + rng.Uniform(-0.15, 0.15)};
    std::vector<double> r = f(u);
    for (size_t k = 0; k < r.size(); ++k)
      r[k] += noise * Normal(seed + 17 * i, static_cast<int>(k));
    out.push_back({u, {true, r, std::vector<double>(r.size(), noise)}});
  }
  return out;
}

std::vector<double> LinearModel(const std::vector<double>& u) {
  return {5 * u[0] - 2 * u[1] + 1, 0.5 * u[0] + 7 * u[1] - 3};
}

}  // namespace

TEST_CASE("response surface recovers a linear model's sensitivities within their standard errors",
          "[unit][calibrate]") {
  const double truth[2][2] = {{5, -2}, {0.5, 7}};
  int outside = 0, entries = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const ResponseSurface s = FitResponseSurface(Cloud(8, {0.5, 0.5}, 0.3, seed, LinearModel),
                                                 {0.5, 0.5}, {.allow_quadratic = false});
    REQUIRE(s.ok);
    CHECK_FALSE(s.quadratic);
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k) {
        ++entries;
        // Unweighted least squares would give noise / (sqrt(K) · sd(u)), sd(u) = 0.15/sqrt(3);
        // the kernel weights and the max(1, χ²/dof) factor may widen it, a little.
        const double ideal = 0.3 / (std::sqrt(8.0) * 0.15 / std::sqrt(3.0));
        CHECK(s.jacobian_sigma(i, k) > 0.5 * ideal);
        CHECK(s.jacobian_sigma(i, k) < 4 * ideal);
        if (std::abs(s.jacobian(i, k) - truth[i][k]) > 2 * s.jacobian_sigma(i, k)) ++outside;
      }
  }
  CHECK(outside <= entries / 5);  // ~5 % expected outside 2σ; 20 % would mean σ is too small
}

TEST_CASE("response surface fits a quadratic when it has twice its coefficients",
          "[unit][calibrate]") {
  // r = 3 (u0 − 0.2)² + u0 u1: at (0.5, 0.5) the gradient is (3·2·0.3 + 0.5, 0.5) = (2.3, 0.5).
  auto quad = [](const std::vector<double>& u) {
    return std::vector<double>{3 * (u[0] - 0.2) * (u[0] - 0.2) + u[0] * u[1]};
  };
  std::vector<Sample> samples = Cloud(12, {0.55, 0.55}, 0.0, 4, quad);  // off-centre cloud
  // Noise-free runs: the noise floor is the only noise the curvature test sees. At the default
  // 0.01 this curvature lowers χ² by 6.7 (< 7.81, the 5 % point for 3 terms): not significant.
  const ResponseSurface q = FitResponseSurface(samples, {0.5, 0.5}, {.noise_floor = 0.001});
  REQUIRE(q.ok);
  CHECK(q.quadratic);
  CHECK(q.points == 12);
  CHECK(q.jacobian(0, 0) == Approx(2.3).margin(1e-6));
  CHECK(q.jacobian(0, 1) == Approx(0.5).margin(1e-6));
  const ResponseSurface l = FitResponseSurface(samples, {0.5, 0.5}, {.allow_quadratic = false});
  REQUIRE(l.ok);
  CHECK(std::abs(l.jacobian(0, 0) - 2.3) > 1e-3);  // a line through a curve is biased here
}

TEST_CASE("response surface keeps a noisy linear residual linear when it could fit a quadratic",
          "[unit][calibrate]") {
  // Twelve noisy samples of a linear model: enough for a quadratic, but its three curvature
  // terms would only fit noise; a row keeps them only when they lower χ² significantly (5 %).
  int linear_rows = 0, rows = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const std::vector<Sample> samples = Cloud(12, {0.5, 0.5}, 0.3, seed, LinearModel);
    const ResponseSurface chosen = FitResponseSurface(samples, {0.5, 0.5});
    REQUIRE(chosen.ok);
    const ResponseSurface linear = FitResponseSurface(samples, {0.5, 0.5}, {.allow_quadratic = false});
    for (int i = 0; i < 2; ++i, ++rows) linear_rows += chosen.jacobian.row(i) == linear.jacobian.row(i);
  }
  CHECK(linear_rows >= rows * 8 / 10);  // ~95 % expected; a quadratic every time would be 0
}

TEST_CASE("response surface ignores failed samples and says when it has too few",
          "[unit][calibrate]") {
  std::vector<Sample> samples = Cloud(2, {0.5, 0.5}, 0.1, 2, LinearModel);
  samples.push_back({{0.5, 0.52}, {}});  // failed
  const ResponseSurface s = FitResponseSurface(samples, {0.5, 0.5});
  CHECK_FALSE(s.ok);
  CHECK(s.message.find("fewer than n + 1") != std::string::npos);
  // Collinear points do not determine the second column.
  std::vector<Sample> line;
  for (int i = 0; i < 5; ++i) {
    const std::vector<double> u{0.3 + 0.1 * i, 0.3 + 0.1 * i};
    line.push_back({u, {true, LinearModel(u), {0.0, 0.0}}});
  }
  CHECK_FALSE(FitResponseSurface(line, {0.5, 0.5}).ok);
}
