#pragma once
// Angle of repose of a settled heap from a Snapshot, as in Alizadeh et al. 2018 (Powder Technol.
// 339:789-800) section 2.5.2 and Fig. 5, and docs/physics.md §5.1:
//  1. surface profile: per cell the top z + R of the highest sphere (surface_profile.h);
//  2. heap height H = max top − base_z_m; keep points with
//     window_low·H ≤ top − base ≤ window_high·H (drops the rounded apex and the toe/run-out);
//  3. a slot (pseudo-2D) heap is split at its apex into a left and a right flank along x; a free
//     conical heap into `sectors` azimuthal sectors around a vertical axis; each flank is fitted
//     by least squares, top = intercept + slope·s (s = horizontal distance from the apex/axis);
//  4. angle = atan(|slope|); the result is the mean over flanks, with their spread.
// Each flank also carries the paper's own two-point value: the horizontal distance between the
// surface points at 10% and 90% of the heap height (Fig. 5); where no grain is, the surface is
// the floor (base_z_m), so a cliff-edged flank on a glued base still falls through 10% of H.
// A flank with too few points is left out (a heap poured against a wall has one flank); with no
// usable flank the result has ok = false and a message, never NaN. Pure functions, thread-safe.
//
//   ReposeAngle a = MeasureSlotHeapAngle(Crop(snap, lo, hi), {.base_z_m = 0.0});
//   if (a.ok) std::printf("%.1f ± %.1f deg\n", a.angle_deg, a.spread_deg);
#include <string>
#include <vector>

#include "objectives/common/snapshot.h"

namespace demcal::objectives {

struct ReposeAngleOptions {
  double base_z_m = 0;       // z of the floor the heap stands on
  double window_low = 0.1;   // fraction of the heap height H: lowest fitted point
  double window_high = 0.9;  // fraction of H: highest fitted point
  double cell_m = 0;         // profile cell width; 0: 1.5 × mean sphere diameter
  int sectors = 16;          // conical heap: azimuthal sectors
  int min_flank_points = 5;  // a flank/sector with fewer points in the window is left out
  // kFit: least squares over the window points (needs min_flank_points). kTwoPoint: the paper's
  // reading for rough heaps (section 2.5.2: "for the higher levels of coating, due to the
  // fluctuations on the heap surface", the horizontal distance between the surface points at 10%
  // and 90% of H) alone; a steep, rough cohesive flank often has too few window points to fit.
  // kFitElseTwoPoint: per flank the fit, and the two-point reading where the fit has too few
  // points — the paper's own practice (fits the sharp flanks of low coating levels, reads two
  // points on the rough ones); a two-point reading needs the toe below window_low·H, which a
  // run-out layer against the box wall can deny, so neither method alone covers every heap.
  enum class Method { kFit, kTwoPoint, kFitElseTwoPoint } method = Method::kFit;

  // False (with the field and bound in *error) for an unusable configuration.
  bool IsValid(std::string* error) const;
};

struct FlankFit {
  double angle_deg = 0;  // atan(|slope|)
  double r_squared = 0;
  int points = 0;  // profile points in the height window
  // Paper Fig. 5: from the surface points at the window heights (first crossings walking out from
  // the apex, linearly interpolated). Like the paper's manual reading it has no outlier guard.
  double two_point_angle_deg = 0;
  bool two_point_ok = false;        // false when the profile does not cross both heights
  double angle_sem_deg = 0;         // standard error of angle_deg from the fit residuals
  double slope = 0;                 // d top / d s; negative for a heap flank
  double intercept_m = 0;           // fitted top at s = 0 (the apex or the axis)
  double s_min_m = 0, s_max_m = 0;  // range of s of the fitted points
  double azimuth_deg = 0;           // outward direction: slot left 180, right 0; sector centre
  std::string label;                // "left", "right", "sector 3"
};

struct ReposeAngle {
  bool ok = false;
  std::string message = "not measured";
  double angle_deg = 0;      // mean over the fitted flanks/sectors
  double spread_deg = 0;     // sample standard deviation over flanks/sectors (0 for one)
  double heap_height_m = 0;  // H = max top − base
  double cell_m = 0;         // profile cell width used
  double apex_s_m = 0;       // slot: x of the apex; conical: 0 (the axis)
  std::vector<FlankFit> flanks;
};

// Pseudo-2D heap: left and right flanks along x (depth along y is collapsed).
ReposeAngle MeasureSlotHeapAngle(const Snapshot& snapshot, const ReposeAngleOptions& options);

// Free conical heap: sectors around the vertical axis through axis_point_m (its z is ignored).
ReposeAngle MeasureConicalHeapAngle(const Snapshot& snapshot, Vec3 axis_point_m,
                                    const ReposeAngleOptions& options);

// The vertical axis of a conical heap when the inflow axis is not known (docs/physics.md §5.1
// step 3): the centroid (x, y) of the spheres whose top is within top_fraction·H of the highest
// top, H = max top − base_z_m. z of the result is base_z_m. False when nothing is above the base.
bool EstimateHeapAxis(const Snapshot& snapshot, double base_z_m, Vec3* axis_point_m,
                      double top_fraction = 0.1);

}  // namespace demcal::objectives
