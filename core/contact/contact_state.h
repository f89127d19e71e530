#pragma once
// The data one contact evaluation reads and writes. A contact is between sphere i and either
// sphere j or a wall; the normal points from j (or the wall) to i. Models in the normal,
// tangential and rolling slots are pure functions of these structs, so each is unit-testable
// on its own and the force loop stays free of virtual calls and allocation.
#include "core/materials/interaction_table.h"
#include "core/math/vec3.h"

// Contact-law functions run once per contact per step; they must be inlined into the force loop
// (GCC's heuristics otherwise keep some as calls once the loop body grows).
#define DEMCAL_HOT_INLINE [[gnu::always_inline]] inline

namespace demcal::core {

// Per-contact memory kept between steps (zeroed when the contact ends). Every field has a
// default: a history made for a new contact must read as "no contact yet", never as whatever the
// stack held (a garbage √a would start JKR's Newton iteration off the branch).
struct ContactHistory {
  Vec3 shear_m;                // accumulated tangential displacement δ_t (docs/physics.md §1.3)
  Vec3 rolling_torque_N_m;     // EPSD spring torque M_k (docs/physics.md §2.2)
  double jkr_sqrt_radius = 0;  // √a of the JKR contact radius last step (m^½); 0 before the first
};

struct ContactGeometry {
  Vec3 normal;                    // unit, from j (or wall) towards i
  double overlap_m = 0;           // δ_n = R_i + R_j − |x_i − x_j| (> 0 pressed; < 0 only for JKR)
  double radius_i_m = 0;          // lever arm of i (its radius)
  double radius_j_m = 0;          // lever arm of j; 0 for a wall
  // EDEM's rolling lever R_i: the distance from body i's centre of mass to the contact point.
  // A free sphere's radius; for a clump member, from the clump's centre (core/contact/clump_levers.h).
  double rolling_lever_i_m = 0;
  double rolling_lever_j_m = 0;   // 0 for a wall
  double effective_radius_m = 0;  // R*
  double effective_mass_kg = 0;   // m*
  double mass_i_kg = 0;
  double mass_j_kg = 0;           // 0 for a wall (infinitely heavy)
  Vec3 relative_velocity_m_s;     // of i's contact point relative to j's (includes spin)
  Vec3 omega_i;
  Vec3 omega_j;                   // zero for a wall
};

// Result of the normal slot, also read by the tangential and rolling slots.
struct NormalForce {
  double elastic_N = 0;         // conservative part (Hertz)
  double total_N = 0;           // elastic + damping, along `normal` (positive = repulsive)
  double stiffness_n = 0;       // tangent stiffness S_n = 2E*sqrt(R* δ) (N/m)
  double secant_kn = 0;         // Hertz secant stiffness (4/3)E*sqrt(R* δ) (N/m)
  double contact_radius_m = 0;  // a = sqrt(R* δ) for Hertz
  double friction_load_N = 0;   // what the Coulomb limit μ_s multiplies
  double rolling_load_N = 0;    // what the rolling limit μ_r multiplies
  double damping_N_s_m = 0;     // normal dashpot coefficient c_n = −2 sqrt(5/6) β sqrt(S_n m*) >= 0
};

// What a contact contributes: force on i (j gets the opposite) and a torque on each body.
struct ContactResult {
  Vec3 force_i;
  Vec3 torque_i;
  Vec3 torque_j;
};

}  // namespace demcal::core
