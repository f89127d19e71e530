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
  // The profile's cell width; > 0 completes the two-point walk with the floor. A profile holds
  // only occupied cells, so where no grain is the surface is the floor (base_z_m): one cell
  // beyond the outermost grain, and inside a gap of at least two cells between neighbouring
  // points (points in cells k and k + j are less than j + 1 cells apart, so 2 cells or more
  // means an empty cell between them). Without it a cliff-edged heap on a glued base (whose
  // spheres are not in the heap) never falls through the low level and reads nothing.
  double cell_m = 0;
};

// Least-squares fit of the window points and the paper's two-point angle. False (with the reason
// in *why_not) when fewer than min_points fall in the window or the flank does not descend.
bool FitFlank(const std::vector<SurfacePoint>& outward_profile, const HeightWindow& window,
              int min_points, FlankFit* flank, std::string* why_not);

// The paper's two-point reading alone (Fig. 5), for rough heaps whose window holds too few points
// for a fit: angle_deg = two_point_angle_deg, and slope/intercept/s range describe the segment
// between the two surface points (for plots). False (with the reason) when the profile, completed
// with the floor (HeightWindow::cell_m), does not cross both window heights walking outward.
bool TwoPointFlank(const std::vector<SurfacePoint>& outward_profile, const HeightWindow& window,
                   FlankFit* flank, std::string* why_not);

}  // namespace demcal::objectives
