#pragma once
// Rolling slot "cdt_relative": LIGGGHTS' constant directional torque (`rolling_friction cdt`,
// LIGGGHTS-PUBLIC src/rolling_model_cdt.h; EDEM's "RVD Rolling Friction"; docs/physics.md §2.1).
//   ω_r = ω_i − ω_j;  M = μ_r F_n R* ω_r/|ω_r| without its n̂ component;  τ_i −= M, τ_j += M.
// F_n is the elastic normal load (damping excluded), R* = R_i R_j/(R_i + R_j) (R_i at a wall,
// whose ω is zero). It differs from "cdt" (EDEM's standard law) in two ways that matter for a
// heap: the lever is R* (R/2 for equal spheres) instead of each grain's R_i, and the torque
// opposes the pair's relative rotation, so two grains rolling together feel none, where "cdt"
// brakes each grain's own spin. Data made with LIGGGHTS' cdt are therefore fitted with this law.
// The direction uses the whole ω_r (torsion included) before the normal part of M is removed,
// as LIGGGHTS does, so a twisting pair feels a smaller rolling torque.
#include <cmath>

#include "core/contact/contact_state.h"

namespace demcal::core {

struct RollingCdtRelative {
  static constexpr const char* kName = "cdt_relative";
  DEMCAL_HOT_INLINE void Apply(const ContactGeometry& g, const ResolvedPair& p,
                               const NormalForce& n, double, ContactHistory&,
                               ContactResult& r) const {
    const Vec3 w = g.omega_i - g.omega_j;
    const double w_norm = Norm(w);
    // Below 1e-12 rad/s the direction is undefined; LIGGGHTS applies no torque at exactly 0.
    if (w_norm <= 1e-12) return;
    Vec3 torque = w * (p.rolling_friction * n.rolling_load_N * g.effective_radius_m / w_norm);
    torque -= Dot(torque, g.normal) * g.normal;
    r.torque_i -= torque;
    r.torque_j += torque;
  }
};

}  // namespace demcal::core
