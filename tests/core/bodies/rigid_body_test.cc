#include "core/bodies/rigid_body.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

using namespace demcal::core;

namespace {

constexpr double kPi = std::numbers::pi;

void Step(RigidState& s, const Vec3& inertia, double dt, DriftScheme scheme) {
  HalfKick(s, {}, dt);
  Drift(s, inertia, dt, scheme);
  HalfKick(s, {}, dt);
}

// Complete elliptic integral of the first kind K(k) by the arithmetic–geometric mean
// (Abramowitz & Stegun 17.6): K = π / (2 AGM(1, √(1 − k²))).
double EllipticK(double k2) {
  double a = 1, b = std::sqrt(1 - k2);
  for (int i = 0; i < 60 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double m = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = m;
  }
  return kPi / (2 * a);
}

// Period of the body-frame angular velocity of a free asymmetric top, I1 < I2 < I3 (Landau &
// Lifshitz, Mechanics §37): for L² > 2E I2, τ = t √((I3 − I2)(L² − 2E I1)/(I1 I2 I3)),
// k² = (I2 − I1)(2E I3 − L²)/((I3 − I2)(L² − 2E I1)), ω2 ∝ sn τ has period 4K(k) in τ. For
// L² < 2E I2 exchange I1 and I3.
double EulerPeriod(Vec3 inertia, double energy, double l2) {
  double i1 = inertia.x, i2 = inertia.y, i3 = inertia.z;
  if (l2 < 2 * energy * i2) std::swap(i1, i3);
  const double rate = std::sqrt((i3 - i2) * (l2 - 2 * energy * i1) / (i1 * i2 * i3));
  const double k2 = (i2 - i1) * (2 * energy * i3 - l2) / ((i3 - i2) * (l2 - 2 * energy * i1));
  return 4 * EllipticK(k2) / rate;
}

}  // namespace

TEST_CASE("rigid: angular velocity is A I^-1 A^T L", "[rigid][unit]") {
  const Vec3 inertia{1, 2, 3};
  const Quaternion q = Quaternion::FromAxisAngle({0.3, -1, 2}, 0.9);
  const RigidState s{q, {0.4, -1.1, 2.0}};
  const Eigen::Matrix3d a = ToRotationMatrix(q);
  const Eigen::Vector3d w = a * Eigen::Vector3d(1, 2, 3).cwiseInverse().asDiagonal() *
                            a.transpose() * Eigen::Vector3d(0.4, -1.1, 2.0);
  const Vec3 got = AngularVelocity(s, inertia);
  CHECK(Norm(got - Vec3{w.x(), w.y(), w.z()}) < 1e-14);
  CHECK(RotationalKineticEnergy(s, inertia) == Approx(0.5 * Dot(got, s.angular_momentum_kg_m2_s)));
  const RigidState back = StateFromAngularVelocity(q, got, inertia);
  CHECK(Norm(back.angular_momentum_kg_m2_s - s.angular_momentum_kg_m2_s) < 1e-14);
}

TEST_CASE("rigid: constant torque about a principal axis spins up exactly", "[rigid][physics]") {
  // From rest, τ along principal axis z of inertia I: L = τ t, θ = τ t²/(2 I). Kick–drift–kick
  // with a constant torque sums ω_{n+½} Δt exactly (the drift rotates about a fixed axis).
  const Vec3 inertia{2e-9, 3e-9, 4e-9};
  const double torque = 1e-7, dt = 1e-5;
  const int steps = 2000;
  RigidState s;
  for (int i = 0; i < steps; ++i) {
    HalfKick(s, {0, 0, torque}, dt);
    Drift(s, inertia, dt);
    HalfKick(s, {0, 0, torque}, dt);
  }
  const double t = steps * dt;
  CHECK(s.angular_momentum_kg_m2_s.z == Approx(torque * t).epsilon(1e-12));
  const double theta = torque * t * t / (2 * inertia.z);
  const Quaternion expected = Quaternion::FromAxisAngle({0, 0, 1}, theta);
  const Vec3 x = Rotate(s.orientation, {1, 0, 0});
  CHECK(Norm(x - Rotate(expected, {1, 0, 0})) < 1e-9);
}

TEST_CASE("rigid: torque-free symmetric top precesses at L / I1", "[rigid][physics]") {
  // Free symmetric top, I1 = I2 (transverse), symmetry axis e3: e3 precesses about the fixed L
  // at Ω = |L| / I1 on a cone of constant half-angle, cos θ = L·e3/|L| (Landau & Lifshitz §33;
  // Goldstein §5.6). Prolate (I3 < I1) and oblate (I3 > I1) tops, tilted initial orientation.
  for (const Vec3 inertia : {Vec3{2, 2, 1}, Vec3{1, 1, 1.8}}) {
    for (const DriftScheme scheme : {DriftScheme::kMidpoint, DriftScheme::kRichardson}) {
      const Quaternion q0 = Quaternion::FromAxisAngle({1, -2, 0.5}, 0.6);
      RigidState s = StateFromAngularVelocity(q0, Rotate(q0, {0.3, 0.1, 1.0}), inertia);
      const Vec3 l = s.angular_momentum_kg_m2_s;
      const Vec3 lhat = l / Norm(l);
      const Vec3 u = Cross(lhat, Vec3{0, 0, 1}) / Norm(Cross(lhat, Vec3{0, 0, 1}));
      const Vec3 v = Cross(lhat, u);
      auto azimuth = [&](const Quaternion& q) {
        const Vec3 e3 = Rotate(q, {0, 0, 1});
        return std::atan2(Dot(e3, v), Dot(e3, u));
      };
      const double cos0 = Dot(Rotate(s.orientation, {0, 0, 1}), lhat);
      const double dt = 1e-3;
      const int steps = 100000;
      double angle = 0, last = azimuth(s.orientation), max_cone_error = 0;
      for (int i = 0; i < steps; ++i) {
        Step(s, inertia, dt, scheme);
        const double a = azimuth(s.orientation);
        angle += std::remainder(a - last, 2 * kPi);
        last = a;
        max_cone_error =
            std::max(max_cone_error, std::abs(Dot(Rotate(s.orientation, {0, 0, 1}), lhat) - cos0));
      }
      const double rate = angle / (steps * dt);
      const double expected = Norm(l) / inertia.x;
      INFO("I = (" << inertia.x << ", " << inertia.y << ", " << inertia.z << "), scheme "
                   << static_cast<int>(scheme) << ": rate " << rate << " vs " << expected);
      CHECK(angle > 4 * kPi);  // several revolutions measured
      CHECK(std::abs(rate / expected - 1) < 1e-2);
      CHECK(max_cone_error < 1e-6);
    }
  }
}

TEST_CASE("rigid: free asymmetric top conserves |L| and energy over 1e5 steps",
          "[rigid][physics]") {
  // I1 < I2 < I3. Rotation close to the intermediate axis is unstable (Dzhanibekov effect): the
  // body flips periodically; the period follows Landau & Lifshitz §37 (EulerPeriod above).
  const Vec3 inertia{1, 2, 3};
  const double dt = 0.01;
  const int steps = 100000;
  struct Start {
    Vec3 omega_body;
    bool intermediate;
  };
  for (const Start start : {Start{{0.01, 1.0, 0.01}, true}, Start{{0.05, 1.0, -0.02}, true},
                            Start{{1.0, 0.3, 0.2}, false}, Start{{0.1, 0.4, 1.0}, false}}) {
    for (const DriftScheme scheme : {DriftScheme::kMidpoint, DriftScheme::kRichardson}) {
      const Quaternion q0 = Quaternion::FromAxisAngle({1, 2, 3}, 0.7);
      RigidState s = StateFromAngularVelocity(q0, Rotate(q0, start.omega_body), inertia);
      const Vec3 l0 = s.angular_momentum_kg_m2_s;
      const double e0 = RotationalKineticEnergy(s, inertia);
      double max_e = 0, max_lb = 0;
      std::vector<double> crossings;  // zero crossings of the body-frame L2
      double prev = InverseRotate(s.orientation, l0).y;
      for (int i = 1; i <= steps; ++i) {
        Step(s, inertia, dt, scheme);
        const Vec3 lb = InverseRotate(s.orientation, s.angular_momentum_kg_m2_s);
        max_e = std::max(max_e, std::abs(RotationalKineticEnergy(s, inertia) / e0 - 1));
        max_lb = std::max(max_lb, std::abs(Norm(lb) / Norm(l0) - 1));
        if ((lb.y > 0) != (prev > 0)) {
          crossings.push_back((i - 1 + prev / (prev - lb.y)) * dt);  // linear interpolation
        }
        prev = lb.y;
      }
      INFO("ω_body = (" << start.omega_body.x << ", " << start.omega_body.y << ", "
                        << start.omega_body.z << "), scheme " << static_cast<int>(scheme)
                        << ": energy drift " << max_e << ", |L_body| drift " << max_lb);
      CHECK(Norm(s.angular_momentum_kg_m2_s - l0) == 0.0);  // no torque: L is untouched
      CHECK(max_lb < 1e-6);
      CHECK(max_e < 1e-4);
      CHECK(std::abs(Norm(s.orientation) - 1) < 1e-14);
      if (start.intermediate) {
        // Flips happen, at the analytic rate: crossings are half a period apart.
        REQUIRE(crossings.size() > 10);
        const double half_period =
            (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
        const double expected = 0.5 * EulerPeriod(inertia, e0, Norm2(l0));
        INFO("half period " << half_period << " vs " << expected);
        CHECK(std::abs(half_period / expected - 1) < 1e-2);
      }
    }
  }
}

TEST_CASE("rigid: the frozen-ω drift is only first order", "[rigid][unit]") {
  // Documents why Drift re-evaluates ω: freezing it for the step drifts the energy of a tumbling
  // top by orders of magnitude more than the midpoint scheme (same step).
  const Vec3 inertia{1, 2, 3};
  auto drift = [&](DriftScheme scheme) {
    RigidState s = StateFromAngularVelocity({}, {0.3, 1.0, 0.2}, inertia);
    const double e0 = RotationalKineticEnergy(s, inertia);
    for (int i = 0; i < 2000; ++i) Step(s, inertia, 0.01, scheme);
    return std::abs(RotationalKineticEnergy(s, inertia) / e0 - 1);
  };
  CHECK(drift(DriftScheme::kFrozen) > 100 * drift(DriftScheme::kMidpoint));
}
