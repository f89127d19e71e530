#pragma once
// Rigid-body rotation for a body with diagonal principal inertia (a clump in its principal
// frame), integrated kick–drift–kick (physics.md §7.2):
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
#include "core/quaternion.h"
#include "core/vec3.h"

namespace demcal::core {

struct RigidState {
  Quaternion orientation;         // body (principal frame) → space
  Vec3 angular_momentum_kg_m2_s;  // L, space frame
};

enum class DriftScheme { kMidpoint, kRichardson, kFrozen };

// ω in the space frame: A I⁻¹ Aᵀ L.
Vec3 AngularVelocity(const RigidState& state, const Vec3& principal_inertia_kg_m2);

// Rotational kinetic energy ½ Σ L_b,i² / I_i (J), L_b = Aᵀ L.
double RotationalKineticEnergy(const RigidState& state, const Vec3& principal_inertia_kg_m2);

// The state with orientation q spinning at space-frame angular velocity ω: L = A I Aᵀ ω.
RigidState StateFromAngularVelocity(const Quaternion& orientation, const Vec3& omega_rad_s,
                                    const Vec3& principal_inertia_kg_m2);

// L += ½ τ Δt.
void HalfKick(RigidState& state, const Vec3& torque_N_m, double dt_s);

// Rotates the orientation over Δt at fixed L and renormalises it.
void Drift(RigidState& state, const Vec3& principal_inertia_kg_m2, double dt_s,
           DriftScheme scheme = DriftScheme::kMidpoint);

}  // namespace demcal::core
