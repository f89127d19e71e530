#include "core/math/quaternion.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/math/random.h"

using namespace demcal::core;

namespace {

Vec3 RandomVec(Rng& rng) { return {rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)}; }

Quaternion RandomRotation(Rng& rng) {
  return Quaternion::FromAxisAngle(RandomVec(rng) + Vec3{1e-3, 0, 0}, rng.Uniform(-3, 3));
}

void RequireNear(const Vec3& a, const Vec3& b, double tol) {
  INFO("a = (" << a.x << ", " << a.y << ", " << a.z << "), b = (" << b.x << ", " << b.y << ", "
               << b.z << ")");
  REQUIRE(Norm(a - b) < tol);
}

}  // namespace

TEST_CASE("quaternion: a quarter turn about z maps x to y", "[quaternion][unit]") {
  const Quaternion q = Quaternion::FromAxisAngle({0, 0, 2}, std::numbers::pi / 2);
  RequireNear(Rotate(q, {1, 0, 0}), {0, 1, 0}, 1e-15);
  RequireNear(Rotate(q, {0, 0, 1}), {0, 0, 1}, 1e-15);
  RequireNear(InverseRotate(q, {0, 1, 0}), {1, 0, 0}, 1e-15);
  REQUIRE(Norm(q) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("quaternion: product composes rotations, conjugate inverts", "[quaternion][unit]") {
  Rng rng(7);
  for (int i = 0; i < 100; ++i) {
    const Quaternion a = RandomRotation(rng), b = RandomRotation(rng);
    const Vec3 v = RandomVec(rng);
    // Hamilton convention: a ⊗ b applies b first.
    RequireNear(Rotate(a * b, v), Rotate(a, Rotate(b, v)), 1e-14);
    RequireNear(Rotate(Conjugate(a), Rotate(a, v)), v, 1e-14);
    RequireNear(InverseRotate(a, Rotate(a, v)), v, 1e-14);
    const Quaternion id = a * Conjugate(a);
    REQUIRE(id.w == Approx(1.0).epsilon(1e-14));
    REQUIRE(Norm(id.vec()) < 1e-15);
    // Rotations preserve length.
    REQUIRE(Norm(Rotate(a, v)) == Approx(Norm(v)).epsilon(1e-14));
  }
}

TEST_CASE("quaternion: rotation matrix round trip", "[quaternion][unit]") {
  Rng rng(11);
  for (int i = 0; i < 100; ++i) {
    const Quaternion q = RandomRotation(rng);
    const Eigen::Matrix3d a = ToRotationMatrix(q);
    REQUIRE((a.transpose() * a - Eigen::Matrix3d::Identity()).norm() < 1e-14);
    REQUIRE(a.determinant() == Approx(1.0).epsilon(1e-14));
    const Vec3 v = RandomVec(rng);
    const Eigen::Vector3d av = a * Eigen::Vector3d(v.x, v.y, v.z);
    RequireNear(Rotate(q, v), {av.x(), av.y(), av.z()}, 1e-14);
    // q and −q are the same rotation; FromRotationMatrix returns w ≥ 0.
    const Quaternion back = FromRotationMatrix(a);
    const double s = q.w < 0 ? -1.0 : 1.0;
    REQUIRE(std::abs(back.w - s * q.w) < 1e-14);
    RequireNear(back.vec(), s * q.vec(), 1e-14);
  }
}

TEST_CASE("quaternion: rotation vector equals axis-angle, incl. tiny angles",
          "[quaternion][unit]") {
  for (double angle : {2.5, 0.3, 1e-3, 1e-5, 1e-9}) {
    const Vec3 axis = Vec3{1, -2, 0.5} / Norm(Vec3{1, -2, 0.5});
    const Quaternion a = Quaternion::FromAxisAngle(axis, angle);
    const Quaternion b = Quaternion::FromRotationVector(angle * axis);
    REQUIRE(std::abs(a.w - b.w) < 1e-16 + 1e-15 * std::abs(a.w));
    RequireNear(a.vec(), b.vec(), 1e-16 + 1e-15 * Norm(a.vec()));
  }
  const Quaternion id = Quaternion::FromRotationVector({0, 0, 0});
  REQUIRE(id.w == 1.0);
  REQUIRE(Norm(id.vec()) == 0.0);
}

TEST_CASE("quaternion: Normalized restores unit length", "[quaternion][unit]") {
  const Quaternion q = Normalized({2, -1, 0.5, 3});
  REQUIRE(Norm(q) == Approx(1.0).epsilon(1e-15));
  REQUIRE(q.w / q.x == Approx(-2.0));
}
