#pragma once
// Crest drop of a measured heap: how far the real top lies below the apex of its fitted flanks,
//   crest_drop = mean over flanks (fitted top at s = 0) − (base + H),
// in metres. A cohesionless heap is a cone to within a grain (drop ≈ 0); adhesion rounds the
// crest (grains stick at the top and the surface bends over: drop > 0) while steepening the
// slope, so it separates adhesion from friction, which only moves the slope. A negative drop is
// a peak steeper than the flanks. Pure function of a ReposeAngle (repose_angle.h); 0 when the
// angle was not measured.
//
//   const double drop_m = CrestDrop(run.angle, run.angle_options.base_z_m);
#include "objectives/metrics/repose_angle.h"

namespace demcal::objectives {

double CrestDrop(const ReposeAngle& angle, double base_z_m);

}  // namespace demcal::objectives
