#pragma once
// Mindlin no-slip tangential spring with history and Coulomb cap, as LIGGGHTS
// `tangential history` (docs/physics.md §1.3):
//   δ_t += v_t dt, projected on the current tangent plane;  F_t = −S_t δ_t − c_t v_t,
//   S_t = 8 G* sqrt(R* δ);  if S_t|δ_t| > μ_s|F_n|: F_t capped to μ_s|F_n| (no damping while
//   sliding) and the spring reset to the cap. (|F_n| is NormalForce::friction_load_N: the
//   total normal force for Hertz–Mindlin, the repulsive part for JKR.)
//   c_t = −2 sqrt(5/6) β sqrt(S_t m*) = c_n sqrt(S_t/S_n), and S_t/S_n = 4G*/E* is a constant
//   of the pair (ResolvedPair::tangential_damping_ratio), which saves a square root per contact.
#include <cmath>

#include "core/contact/contact_state.h"

namespace demcal::core {

struct MindlinTangential {
  DEMCAL_HOT_INLINE static Vec3 Compute(const ContactGeometry& g, const ResolvedPair& p, const NormalForce& n,
                      double dt, ContactHistory& h) {
    const Vec3 v_t = g.relative_velocity_m_s - Dot(g.relative_velocity_m_s, g.normal) * g.normal;
    h.shear_m += v_t * dt;
    h.shear_m -= Dot(h.shear_m, g.normal) * g.normal;
    const double s_t = 8.0 * p.effective_shear_Pa * n.contact_radius_m;
    Vec3 f_t = -s_t * h.shear_m;
    const double f_max = p.sliding_friction * n.friction_load_N;
    const double f_t2 = Norm2(f_t);
    if (f_t2 > f_max * f_max) {
      f_t *= f_max / std::sqrt(f_t2);
      h.shear_m = f_t * (-1.0 / s_t);
    } else {
      f_t -= (n.damping_N_s_m * p.tangential_damping_ratio) * v_t;
    }
    return f_t;
  }
};

}  // namespace demcal::core
