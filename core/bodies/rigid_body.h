#pragma once
// Rigid-body rotation for a body with diagonal principal inertia (a clump in its principal
// frame), integrated kick–drift–kick (docs/physics.md §7.2):
//   HalfKick:  L ← L + ½ τ Δt                       (torque τ and L in the space frame)
//   Drift:     q ← exp(ω Δt) ⊗ q, then |q| ← 1      (rotation by |ω|Δt about ω̂, space frame)
//   HalfKick:  with the torque of the new orientation.
// With ω = A(q) I⁻¹ A(q)ᵀ L, the space-frame angular velocity. The drift rotates by the exact
// rotation of a constant ω; because ω changes as the body turns (L is fixed during the drift,
// the body-frame L is not), the scheme re-evaluates ω inside the step:
//   kMidpoint   ω at the half-rotated orientation, then one full rotation by it (default;
//               second order).
//   kRichardson the LAMMPS fix rigid "Richardson iteration" (MathExtra::richardson) with exact
//               rotations instead of its linearised dq = ½ ω ⊗ q Δt: q = 2 q_{½,½} − q_full.
//   kFrozen     ω of the start orientation for the whole step (first order; for comparison).
// Without torque L is exactly constant; |Aᵀ L| and the energy ½ L·ω are conserved to the
// integrator's accuracy (measured in rigid_body_test.cc).
//
// Units: inertia kg·m², L kg·m²/s, torque N·m, ω rad/s, Δt s. Principal moments must be > 0.
// Plain value state, pure functions; thread-safe for distinct states.
//
// Usage (one time step of size dt):
//   HalfKick(state, torque, dt);
//   Drift(state, clump.principal_inertia_kg_m2, dt);
//   torque = ...;  // forces at the new orientation
//   HalfKick(state, torque, dt);
#include "core/math/quaternion.h"
#include "core/math/vec3.h"

namespace demcal::core {

struct RigidState {
  Quaternion orientation;         // body (principal frame) → space
  Vec3 angular_momentum_kg_m2_s;  // L, space frame
};

enum class DriftScheme { kMidpoint, kRichardson, kFrozen };

namespace rigid_detail {
// Defined here (not in rigid_body.cc) because they run once or more per clump per step and
// must inline into the integration loops.
inline Vec3 Scale(const Vec3& v, const Vec3& by) { return {v.x * by.x, v.y * by.y, v.z * by.z}; }
// One division instead of three (a division's latency dominates this short computation).
inline Vec3 Reciprocal(const Vec3& v) {
  const double r = 1 / (v.x * v.y * v.z);
  return {v.y * v.z * r, v.x * v.z * r, v.x * v.y * r};
}

// ω = A I⁻¹ Aᵀ L with the reciprocal moments precomputed.
inline Vec3 Omega(const Quaternion& q, const Vec3& l, const Vec3& inverse_inertia) {
  return Rotate(q, Scale(InverseRotate(q, l), inverse_inertia));
}

inline Quaternion Turn(const Vec3& omega, double dt, const Quaternion& q) {
  return Quaternion::FromRotationVector(omega * dt) * q;
}

// The midpoint drift in its two halves, for loops over many bodies that run all first halves,
// then all second halves (ParticleSystem::KickDrift): each half is a long chain of dependent
// operations, and shorter loop bodies let the processor overlap several bodies' chains.
//   the orientation half a step on at the start ω;
inline Quaternion MidpointHalfTurn(const RigidState& s, const Vec3& inverse_inertia, double dt) {
  const Quaternion& q = s.orientation;
  return Turn(Omega(q, s.angular_momentum_kg_m2_s, inverse_inertia), 0.5 * dt, q);
}
//   the start orientation turned a full step at the ω of the half-turned one, renormalised.
inline Quaternion MidpointFullTurn(const RigidState& s, const Quaternion& half,
                                   const Vec3& inverse_inertia, double dt) {
  return Normalized(Turn(Omega(half, s.angular_momentum_kg_m2_s, inverse_inertia), dt, s.orientation));
}
}  // namespace rigid_detail

// ω in the space frame: A I⁻¹ Aᵀ L.
inline Vec3 AngularVelocity(const RigidState& state, const Vec3& principal_inertia_kg_m2) {
  return rigid_detail::Omega(state.orientation, state.angular_momentum_kg_m2_s,
                             rigid_detail::Reciprocal(principal_inertia_kg_m2));
}

// Rotational kinetic energy ½ Σ L_b,i² / I_i (J), L_b = Aᵀ L.
double RotationalKineticEnergy(const RigidState& state, const Vec3& principal_inertia_kg_m2);

// The state with orientation q spinning at space-frame angular velocity ω: L = A I Aᵀ ω.
RigidState StateFromAngularVelocity(const Quaternion& orientation, const Vec3& omega_rad_s,
                                    const Vec3& principal_inertia_kg_m2);

// L += ½ τ Δt.
inline void HalfKick(RigidState& state, const Vec3& torque_N_m, double dt_s) {
  state.angular_momentum_kg_m2_s += (0.5 * dt_s) * torque_N_m;
}

// Rotates the orientation over Δt at fixed L and renormalises it.
inline void Drift(RigidState& state, const Vec3& principal_inertia_kg_m2, double dt_s,
                  DriftScheme scheme = DriftScheme::kMidpoint) {
  using rigid_detail::Omega, rigid_detail::Turn;
  const Quaternion q = state.orientation;
  const Vec3& l = state.angular_momentum_kg_m2_s;
  const Vec3 inverse_inertia = rigid_detail::Reciprocal(principal_inertia_kg_m2);
  if (scheme == DriftScheme::kMidpoint) {
    const Quaternion half = rigid_detail::MidpointHalfTurn(state, inverse_inertia, dt_s);
    state.orientation = rigid_detail::MidpointFullTurn(state, half, inverse_inertia, dt_s);
    return;
  }
  const Vec3 w0 = Omega(q, l, inverse_inertia);
  if (scheme == DriftScheme::kFrozen) {
    state.orientation = Normalized(Turn(w0, dt_s, q));
    return;
  }
  // kRichardson
  const Quaternion full = Turn(w0, dt_s, q);
  const Quaternion half = Turn(w0, 0.5 * dt_s, q);
  const Quaternion two_halves = Turn(Omega(half, l, inverse_inertia), 0.5 * dt_s, half);
  const Quaternion next{2 * two_halves.w - full.w, 2 * two_halves.x - full.x,
                        2 * two_halves.y - full.y, 2 * two_halves.z - full.z};
  state.orientation = Normalized(next);
}

}  // namespace demcal::core
