#pragma once
// Quaternion: a unit quaternion q = (w, x, y, z) describing the orientation of a rigid body as
// the rotation body frame → space frame: v_space = q ⊗ (0, v_body) ⊗ q*. Hamilton convention
// (i² = j² = k² = ijk = −1), so Rotate(a ⊗ b, v) = Rotate(a, Rotate(b, v)): "first b, then a".
// Dimensionless. Plain value type (32 bytes, trivially copyable); every function is pure and
// thread-safe. Functions that need a unit quaternion say so; Normalized() restores |q| = 1 after
// round-off accumulates (the rigid-body integrator does it every step).
//
// Usage:
//   Quaternion q = Quaternion::FromAxisAngle({0, 0, 1}, M_PI / 2);   // 90° about z
//   Vec3 v = Rotate(q, {1, 0, 0});                                     // ≈ (0, 1, 0)
//   Eigen::Matrix3d a = ToRotationMatrix(q);   // columns = body axes expressed in space
#include <Eigen/Dense>
#include <cmath>

#include "core/math/vec3.h"

namespace demcal::core {

struct Quaternion {
  double w = 1, x = 0, y = 0, z = 0;  // identity by default

  constexpr Quaternion() = default;
  constexpr Quaternion(double w_, double x_, double y_, double z_) : w(w_), x(x_), y(y_), z(z_) {}

  constexpr Vec3 vec() const { return {x, y, z}; }

  // Rotation by `angle_rad` (right-hand rule) about `axis`; the axis need not be normalised but
  // must be non-zero.
  static Quaternion FromAxisAngle(const Vec3& axis, double angle_rad) {
    const Vec3 u = axis / Norm(axis);
    const double s = std::sin(0.5 * angle_rad);
    return {std::cos(0.5 * angle_rad), s * u.x, s * u.y, s * u.z};
  }

  // Exponential map: the rotation by angle |θ| about θ/|θ| (θ = ω Δt for a constant angular
  // velocity ω over Δt); identity for 0. Below 0.1 rad (every DEM time step) cos(|θ|/2) and
  // sin(|θ|/2)/|θ| come from their Taylor series to the h⁸ term (h = |θ|/2 < 0.05: the first
  // omitted term is < 3e-20, below double round-off), which keeps sin/cos calls out of the
  // clump integrator; no square root is needed either.
  static Quaternion FromRotationVector(const Vec3& theta) {
    const double angle2 = Norm2(theta);
    if (angle2 < 1e-2) {
      const double h2 = 0.25 * angle2;  // half angle squared; multiplications only (no division)
      const double c = 1 - h2 * (1.0 / 2) * (1 - h2 * (1.0 / 12) * (1 - h2 * (1.0 / 30) * (1 - h2 * (1.0 / 56))));
      const double k =
          0.5 * (1 - h2 * (1.0 / 6) * (1 - h2 * (1.0 / 20) * (1 - h2 * (1.0 / 42) * (1 - h2 * (1.0 / 72)))));
      return {c, k * theta.x, k * theta.y, k * theta.z};
    }
    const double angle = std::sqrt(angle2), half = 0.5 * angle;
    const double k = std::sin(half) / angle;
    return {std::cos(half), k * theta.x, k * theta.y, k * theta.z};
  }
};

// Hamilton product a ⊗ b (apply b first, then a).
constexpr Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

constexpr Quaternion Conjugate(const Quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }

constexpr double Norm2(const Quaternion& q) {
  return q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
}
inline double Norm(const Quaternion& q) { return std::sqrt(Norm2(q)); }

// q / |q|; |q| must be non-zero.
inline Quaternion Normalized(const Quaternion& q) {
  const double s = 1.0 / Norm(q);
  return {q.w * s, q.x * s, q.y * s, q.z * s};
}

// Rotates v by the unit quaternion q (body → space): q ⊗ v ⊗ q*, evaluated as
// v + 2w (u × v) + 2 u × (u × v) with u = vec(q).
constexpr Vec3 Rotate(const Quaternion& q, const Vec3& v) {
  const Vec3 u = q.vec();
  const Vec3 t = 2.0 * Cross(u, v);
  return v + q.w * t + Cross(u, t);
}

// Inverse rotation (space → body) by the unit quaternion q: q* ⊗ v ⊗ q.
constexpr Vec3 InverseRotate(const Quaternion& q, const Vec3& v) { return Rotate(Conjugate(q), v); }

// Rotation matrix A(q) of a unit quaternion: v_space = A v_body; column i is body axis i.
inline Eigen::Matrix3d ToRotationMatrix(const Quaternion& q) {
  return Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
}

// Unit quaternion of a proper rotation matrix (orthonormal, det = +1), with w ≥ 0.
inline Quaternion FromRotationMatrix(const Eigen::Matrix3d& a) {
  Eigen::Quaterniond e(a);
  e.normalize();
  if (e.w() < 0) e.coeffs() *= -1.0;
  return {e.w(), e.x(), e.y(), e.z()};
}

}  // namespace demcal::core
