#pragma once
// Landing depth of a tracked granule (Alizadeh et al. 2018, section 3.5, Fig. 17): how far below
// the local heap surface its centre lies when it first comes to rest after its first impact. The
// paper's mechanism: uncoated EP, denser and rounder than BP, push into the heap where they land
// (depth > 0, buried); coated EP stick where they touch and ride the surface layer (depth ≈ −r,
// lying on the surface). The settled heap's depth (TrackedGranule::penetration) mixes this with
// the burial by everything poured later; the landing depth is taken before that.
//
// "At rest": the first sample at or after the impact whose speed is below rest_speed_m_s and
// whose column has a surface (GranuleSample::has_surface). A grain still moving at the end of its
// track has no landing depth.
#include <optional>

#include "experiments/segregation/segregation_experiment.h"

namespace demcal::objectives {

struct LandingOptions {
  // Grains avalanching on a heap surface move at a few 0.1 m/s; 0.05 m/s is well below that and
  // well above the creep of a settled heap at reduced stiffness.
  double rest_speed_m_s = 0.05;
};

// Surface height − centre height (m) at the first rest after the impact; nullopt without an
// impact or without such a sample.
std::optional<double> LandingDepthM(const TrackedGranule& granule, const LandingOptions& options);

}  // namespace demcal::objectives
