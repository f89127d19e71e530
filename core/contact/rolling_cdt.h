#pragma once
// Rolling slot "cdt": EDEM's "Standard Rolling Friction", a constant directional torque
// (Sakaguchi et al. 1993; Ai et al. 2011 type A; docs/physics.md §2.1):
//   τ_i = −μ_r F_n R_i ω̂_i,  τ_j = −μ_r F_n R_j ω̂_j   (per body, elastic F_n),
// R_i the distance from body i's centre of mass to the contact point (ContactGeometry's
// rolling levers: a free sphere's radius, a clump member's distance from its clump's centre).
// Known weakness: the torque does not vanish as ω → 0, so static heaps jitter; prefer "epsd".
#include <cmath>

#include "core/contact/contact_state.h"

namespace demcal::core {

struct RollingCdt {
  static constexpr const char* kName = "cdt";
  static constexpr bool kReadsRollingLever = true;  // ContactGeometry::rolling_lever_{i,j}_m
  DEMCAL_HOT_INLINE void Apply(const ContactGeometry& g, const ResolvedPair& p, const NormalForce& n, double,
             ContactHistory&, ContactResult& r) const {
    const double magnitude = p.rolling_friction * n.rolling_load_N;
    r.torque_i -= TorqueDirection(g.omega_i) * (magnitude * g.rolling_lever_i_m);
    r.torque_j -= TorqueDirection(g.omega_j) * (magnitude * g.rolling_lever_j_m);
  }

 private:
  static Vec3 TorqueDirection(const Vec3& omega) {
    const double w = Norm(omega);
    return w > 1e-12 ? omega / w : Vec3{};
  }
};

}  // namespace demcal::core
