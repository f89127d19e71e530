#include "core/bodies/rigid_body.h"

namespace demcal::core {

using rigid_detail::Reciprocal;
using rigid_detail::Scale;

double RotationalKineticEnergy(const RigidState& state, const Vec3& principal_inertia_kg_m2) {
  const Vec3 lb = InverseRotate(state.orientation, state.angular_momentum_kg_m2_s);
  return 0.5 * Dot(lb, Scale(lb, Reciprocal(principal_inertia_kg_m2)));
}

RigidState StateFromAngularVelocity(const Quaternion& orientation, const Vec3& omega_rad_s,
                                    const Vec3& principal_inertia_kg_m2) {
  const Vec3 wb = InverseRotate(orientation, omega_rad_s);
  return {orientation, Rotate(orientation, Scale(wb, principal_inertia_kg_m2))};
}

}  // namespace demcal::core
