#include "core/rigid_body.h"

namespace demcal::core {
namespace {

Vec3 Scale(const Vec3& v, const Vec3& by) { return {v.x * by.x, v.y * by.y, v.z * by.z}; }
Vec3 Reciprocal(const Vec3& v) { return {1 / v.x, 1 / v.y, 1 / v.z}; }

// ω = A I⁻¹ Aᵀ L with the reciprocal moments precomputed (one division per axis per call site).
Vec3 Omega(const Quaternion& q, const Vec3& l, const Vec3& inverse_inertia) {
  return Rotate(q, Scale(InverseRotate(q, l), inverse_inertia));
}

Quaternion Turn(const Vec3& omega, double dt, const Quaternion& q) {
  return Quaternion::FromRotationVector(omega * dt) * q;
}

}  // namespace

Vec3 AngularVelocity(const RigidState& state, const Vec3& principal_inertia_kg_m2) {
  return Omega(state.orientation, state.angular_momentum_kg_m2_s,
               Reciprocal(principal_inertia_kg_m2));
}

double RotationalKineticEnergy(const RigidState& state, const Vec3& principal_inertia_kg_m2) {
  const Vec3 lb = InverseRotate(state.orientation, state.angular_momentum_kg_m2_s);
  return 0.5 * Dot(lb, Scale(lb, Reciprocal(principal_inertia_kg_m2)));
}

RigidState StateFromAngularVelocity(const Quaternion& orientation, const Vec3& omega_rad_s,
                                    const Vec3& principal_inertia_kg_m2) {
  const Vec3 wb = InverseRotate(orientation, omega_rad_s);
  return {orientation, Rotate(orientation, Scale(wb, principal_inertia_kg_m2))};
}

void HalfKick(RigidState& state, const Vec3& torque_N_m, double dt_s) {
  state.angular_momentum_kg_m2_s += (0.5 * dt_s) * torque_N_m;
}

void Drift(RigidState& state, const Vec3& principal_inertia_kg_m2, double dt_s,
           DriftScheme scheme) {
  const Quaternion q = state.orientation;
  const Vec3& l = state.angular_momentum_kg_m2_s;
  const Vec3 inverse_inertia = Reciprocal(principal_inertia_kg_m2);
  const Vec3 w0 = Omega(q, l, inverse_inertia);
  Quaternion next;
  switch (scheme) {
    case DriftScheme::kFrozen:
      next = Turn(w0, dt_s, q);
      break;
    case DriftScheme::kMidpoint: {
      const Vec3 wh = Omega(Turn(w0, 0.5 * dt_s, q), l, inverse_inertia);
      next = Turn(wh, dt_s, q);
      break;
    }
    case DriftScheme::kRichardson: {
      const Quaternion full = Turn(w0, dt_s, q);
      const Quaternion half = Turn(w0, 0.5 * dt_s, q);
      const Quaternion two_halves = Turn(Omega(half, l, inverse_inertia), 0.5 * dt_s, half);
      next = {2 * two_halves.w - full.w, 2 * two_halves.x - full.x, 2 * two_halves.y - full.y,
              2 * two_halves.z - full.z};
      break;
    }
  }
  state.orientation = Normalized(next);
}

}  // namespace demcal::core
