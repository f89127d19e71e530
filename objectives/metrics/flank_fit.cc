#include "objectives/metrics/flank_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "objectives/metrics/line_fit.h"

namespace demcal::objectives {

namespace {

double Degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

double RelativeHeight(const SurfacePoint& p, const HeightWindow& w) {
  return (p.top_m - w.base_z_m) / w.heap_height_m;
}

// The outward profile with the floor where no grain is (HeightWindow::cell_m): a floor point one
// cell past a point followed by a gap of two cells or more, and one past the outermost point.
std::vector<SurfacePoint> WithFloor(const std::vector<SurfacePoint>& profile,
                                    const HeightWindow& w) {
  if (!(w.cell_m > 0) || profile.empty()) return profile;
  std::vector<SurfacePoint> out;
  out.reserve(profile.size() + 2);
  for (size_t i = 0; i < profile.size(); ++i) {
    out.push_back(profile[i]);
    const bool last = i + 1 == profile.size();
    if (last || profile[i + 1].s_m - profile[i].s_m >= 2 * w.cell_m)
      out.push_back({profile[i].s_m + w.cell_m, w.base_z_m});
  }
  return out;
}

// s where the profile, walked outward, first drops to `level` (fraction of H), by linear
// interpolation between the last point above and the first at or below. False when the first
// point is already below (the crossing is not seen) or the profile never gets there.
bool OutwardCrossing(const std::vector<SurfacePoint>& profile, const HeightWindow& w, double level,
                     double* s_m) {
  for (size_t i = 0; i < profile.size(); ++i) {
    const double here = RelativeHeight(profile[i], w);
    if (here > level) continue;
    if (i == 0) return false;
    const double before = RelativeHeight(profile[i - 1], w);
    const double t = (before - level) / (before - here);
    *s_m = profile[i - 1].s_m + t * (profile[i].s_m - profile[i - 1].s_m);
    return true;
  }
  return false;
}

// Paper Fig. 5: the height difference between the window's two levels over the horizontal
// distance between the surface points at those heights.
// s_high, s_low: where the two levels are crossed (set when the angle is ok).
void TwoPointAngle(const std::vector<SurfacePoint>& profile, const HeightWindow& w,
                   FlankFit* flank, double* s_high_m = nullptr, double* s_low_m = nullptr) {
  double s_high = 0, s_low = 0;
  const std::vector<SurfacePoint> surface = WithFloor(profile, w);
  flank->two_point_ok = OutwardCrossing(surface, w, w.high, &s_high) &&
                        OutwardCrossing(surface, w, w.low, &s_low) && s_low > s_high;
  if (s_high_m) *s_high_m = s_high;
  if (s_low_m) *s_low_m = s_low;
  flank->two_point_angle_deg =
      flank->two_point_ok
          ? Degrees(std::atan((w.high - w.low) * w.heap_height_m / (s_low - s_high)))
          : 0.0;
}

}  // namespace

bool FitFlank(const std::vector<SurfacePoint>& outward_profile, const HeightWindow& window,
              int min_points, FlankFit* flank, std::string* why_not) {
  std::vector<double> s, top;
  for (const SurfacePoint& p : outward_profile) {
    const double h = RelativeHeight(p, window);
    if (h < window.low || h > window.high) continue;
    s.push_back(p.s_m);
    top.push_back(p.top_m);
  }
  if (static_cast<int>(s.size()) < min_points) {
    *why_not = std::to_string(s.size()) + " points in the height window (need " +
               std::to_string(min_points) + ")";
    return false;
  }
  const LineFit fit = FitLine(s, top);
  if (!fit.ok || !(fit.slope < 0)) {
    *why_not = "the surface does not descend away from the apex";
    return false;
  }
  flank->angle_deg = Degrees(std::atan(-fit.slope));
  // d atan(m)/dm = 1/(1 + m²): the slope's standard error carried to the angle.
  flank->angle_sem_deg = Degrees(fit.slope_sem / (1 + fit.slope * fit.slope));
  flank->r_squared = fit.r_squared;
  flank->points = fit.points;
  flank->slope = fit.slope;
  flank->intercept_m = fit.intercept;
  flank->s_min_m = *std::min_element(s.begin(), s.end());
  flank->s_max_m = *std::max_element(s.begin(), s.end());
  TwoPointAngle(outward_profile, window, flank);
  return true;
}

bool TwoPointFlank(const std::vector<SurfacePoint>& outward_profile, const HeightWindow& window,
                   FlankFit* flank, std::string* why_not) {
  double s_high = 0, s_low = 0;
  TwoPointAngle(outward_profile, window, flank, &s_high, &s_low);
  if (!flank->two_point_ok) {
    *why_not = "the surface does not fall through both window heights walking out from the apex";
    return false;
  }
  flank->angle_deg = flank->two_point_angle_deg;
  flank->slope = -(window.high - window.low) * window.heap_height_m / (s_low - s_high);
  flank->intercept_m = window.base_z_m + window.high * window.heap_height_m - flank->slope * s_high;
  flank->s_min_m = s_high;
  flank->s_max_m = s_low;
  flank->points = 0;
  for (const SurfacePoint& p : outward_profile) {
    const double h = RelativeHeight(p, window);
    flank->points += h >= window.low && h <= window.high;
  }
  return true;
}

}  // namespace demcal::objectives
