#pragma once
// One flank of a heap: a surface profile ordered outward from the apex (s = horizontal distance
// from the apex or axis, s ≥ 0), fitted inside the height window of repose_angle.h. Shared by the
// slot heap (two flanks) and the conical heap (one per sector).
#include <string>
#include <vector>

#include "objectives/metrics/repose_angle.h"
#include "objectives/metrics/surface_profile.h"

namespace demcal::objectives {

struct HeightWindow {
  double base_z_m = 0;
  double heap_height_m = 0;      // H > 0
  double low = 0.1, high = 0.9;  // fractions of H
};

// Least-squares fit of the window points and the paper's two-point angle. False (with the reason
// in *why_not) when fewer than min_points fall in the window or the flank does not descend.
bool FitFlank(const std::vector<SurfacePoint>& outward_profile, const HeightWindow& window,
              int min_points, FlankFit* flank, std::string* why_not);

// The paper's two-point reading alone (Fig. 5), for rough heaps whose window holds too few points
// for a fit: angle_deg = two_point_angle_deg, and slope/intercept/s range describe the segment
// between the two surface points (for plots). False (with the reason) when the profile does not
// cross both window heights walking outward.
bool TwoPointFlank(const std::vector<SurfacePoint>& outward_profile, const HeightWindow& window,
                   FlankFit* flank, std::string* why_not);

}  // namespace demcal::objectives
