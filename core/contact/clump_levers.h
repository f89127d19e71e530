#pragma once
// The rolling levers of clump members. EDEM's constant-torque rolling friction (docs/physics.md
// §2.1, `cdt`) takes as body i's lever R_i "the distance of the contact point from the centre of
// mass": for a free sphere its radius, for a clump the distance from the clump's centre of mass,
// which for the end sphere of a chain is several member radii. The contact point lies on the
// normal at depth r − δ/2 inside each sphere (the middle of the overlap). A free sphere keeps its
// radius rather than r − δ/2 (δ/2r ≈ 1e-3 at the stiffnesses used), so sphere scenes are
// unchanged to the last bit. Only a law that reads the levers (ContactModel::kReadsRollingLever,
// `cdt`) has them set; the others keep their sources' radii.
//
// Thread-safety: pure functions.
#include <cstdint>
#include <span>

#include "core/bodies/particles.h"
#include "core/contact/contact_state.h"

namespace demcal::core {

// The clumps' centres of mass, indexed by Particles::body; empty when a scene has no clumps.
using BodyCentres = std::span<const Vec3>;

// For the clump members among i and j (j < 0: a wall), replaces the radius set as rolling lever
// by the distance from the member's clump centre to the contact point. `g` holds the contact's
// normal (from j or the wall towards i) and overlap.
DEMCAL_HOT_INLINE void SetClumpLevers(const Particles& p, BodyCentres centres, size_t i, int64_t j,
                                      ContactGeometry& g) {
  const double half_overlap = 0.5 * g.overlap_m;
  if (p.body[i] >= 0) {
    const Vec3 arm = p.position_m[i] - centres[p.body[i]];
    g.rolling_lever_i_m = Norm(arm - g.normal * (p.radius_m[i] - half_overlap));
  }
  if (j >= 0 && p.body[j] >= 0) {
    const Vec3 arm = p.position_m[j] - centres[p.body[j]];
    g.rolling_lever_j_m = Norm(arm + g.normal * (p.radius_m[j] - half_overlap));
  }
}

}  // namespace demcal::core
