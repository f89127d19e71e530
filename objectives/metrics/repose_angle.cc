#include "objectives/metrics/repose_angle.h"

#include <algorithm>
#include <cmath>

#include "objectives/metrics/flank_fit.h"
#include "objectives/metrics/surface_profile.h"

namespace demcal::objectives {

bool ReposeAngleOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& what) {
    if (error) *error = "ReposeAngleOptions: " + what;
    return false;
  };
  if (!std::isfinite(base_z_m)) return fail("base_z_m must be finite");
  if (!(window_low >= 0 && window_low < window_high && window_high <= 1))
    return fail("need 0 <= window_low < window_high <= 1");
  if (!(cell_m >= 0 && std::isfinite(cell_m))) return fail("cell_m must be >= 0 (0: automatic)");
  if (sectors < 1) return fail("sectors must be >= 1");
  if (min_flank_points < 3) return fail("min_flank_points must be >= 3");
  return true;
}

namespace {

// Checks the options and the spheres and picks the cell width; false with result->message set.
bool Prepare(const Snapshot& snapshot, const ReposeAngleOptions& options, ReposeAngle* result) {
  std::string error;
  if (!options.IsValid(&error)) {
    result->message = error;
    return false;
  }
  if (snapshot.spheres.empty()) {
    result->message = "no spheres in the snapshot";
    return false;
  }
  double diameter_sum = 0;
  for (const SurfaceSphere& sphere : snapshot.spheres) {
    if (!core::IsFinite(sphere.position_m) || !(sphere.radius_m > 0) ||
        !std::isfinite(sphere.radius_m)) {
      result->message = "a sphere has a non-finite position or a non-positive radius";
      return false;
    }
    diameter_sum += 2 * sphere.radius_m;
  }
  result->cell_m = options.cell_m > 0
                       ? options.cell_m
                       : 1.5 * diameter_sum / static_cast<double>(snapshot.spheres.size());
  double top = -INFINITY;
  for (const SurfaceSphere& sphere : snapshot.spheres)
    top = std::max(top, sphere.position_m.z + sphere.radius_m);
  result->heap_height_m = top - options.base_z_m;
  if (!(result->heap_height_m > 0)) {
    result->message = "no heap: no sphere reaches above base_z_m";
    return false;
  }
  return true;
}

HeightWindow WindowOf(const ReposeAngle& result, const ReposeAngleOptions& options) {
  return {options.base_z_m, result.heap_height_m, options.window_low, options.window_high,
          result.cell_m};
}

// Fits one flank and keeps it, or notes why it was left out.
void AddFlank(const std::vector<SurfacePoint>& outward, const HeightWindow& window,
              const ReposeAngleOptions& options, FlankFit flank, ReposeAngle* result,
              std::string* skipped) {
  std::string why_not;
  using Method = ReposeAngleOptions::Method;
  bool ok = options.method != Method::kTwoPoint &&
            FitFlank(outward, window, options.min_flank_points, &flank, &why_not);
  if (!ok && options.method != Method::kFit) {
    std::string two_point_why_not;
    ok = TwoPointFlank(outward, window, &flank, &two_point_why_not);
    why_not += (why_not.empty() ? "" : "; two points: ") + two_point_why_not;
  }
  if (ok) {
    result->flanks.push_back(std::move(flank));
  } else {
    *skipped += (skipped->empty() ? "" : "; ") + flank.label + ": " + why_not;
  }
}

// Mean and sample standard deviation over the fitted flanks.
void Summarise(const std::string& skipped, ReposeAngle* result) {
  const size_t n = result->flanks.size();
  if (n == 0) {
    result->message = "no flank could be fitted (" + skipped + ")";
    return;
  }
  double sum = 0;
  for (const FlankFit& f : result->flanks) sum += f.angle_deg;
  result->angle_deg = sum / static_cast<double>(n);
  double ss = 0;
  for (const FlankFit& f : result->flanks) ss += std::pow(f.angle_deg - result->angle_deg, 2);
  result->spread_deg = n > 1 ? std::sqrt(ss / static_cast<double>(n - 1)) : 0.0;
  result->ok = true;
  result->message = skipped.empty() ? "ok" : "left out " + skipped;
}

}  // namespace

ReposeAngle MeasureSlotHeapAngle(const Snapshot& snapshot, const ReposeAngleOptions& options) {
  ReposeAngle result;
  if (!Prepare(snapshot, options, &result)) return result;
  const std::vector<SurfacePoint> profile = SlotProfile(snapshot, result.cell_m);
  const int apex = ApexIndex(profile);
  result.apex_s_m = profile[apex].s_m;
  std::vector<SurfacePoint> left, right;  // outward from the apex, s = distance from it
  for (int i = apex; i >= 0; --i)
    left.push_back({result.apex_s_m - profile[i].s_m, profile[i].top_m});
  for (size_t i = apex; i < profile.size(); ++i)
    right.push_back({profile[i].s_m - result.apex_s_m, profile[i].top_m});
  const HeightWindow window = WindowOf(result, options);
  std::string skipped;
  AddFlank(left, window, options, {.azimuth_deg = 180, .label = "left"}, &result, &skipped);
  AddFlank(right, window, options, {.azimuth_deg = 0, .label = "right"}, &result, &skipped);
  Summarise(skipped, &result);
  return result;
}

ReposeAngle MeasureConicalHeapAngle(const Snapshot& snapshot, Vec3 axis_point_m,
                                    const ReposeAngleOptions& options) {
  ReposeAngle result;
  if (!Prepare(snapshot, options, &result)) return result;
  if (!std::isfinite(axis_point_m.x) || !std::isfinite(axis_point_m.y)) {
    result.message = "the axis point must be finite";
    return result;
  }
  const int n = options.sectors;
  const std::vector<std::vector<SurfacePoint>> sectors =
      SectorProfiles(snapshot, axis_point_m, n, result.cell_m);
  const HeightWindow window = WindowOf(result, options);
  std::string skipped;
  for (int k = 0; k < n; ++k) {
    const FlankFit flank{.azimuth_deg = (k + 0.5) * 360.0 / n,
                         .label = "sector " + std::to_string(k)};
    AddFlank(sectors[k], window, options, flank, &result, &skipped);
  }
  Summarise(skipped, &result);
  return result;
}

bool EstimateHeapAxis(const Snapshot& snapshot, double base_z_m, Vec3* axis_point_m,
                      double top_fraction) {
  double top = -INFINITY;
  for (const SurfaceSphere& sphere : snapshot.spheres)
    top = std::max(top, sphere.position_m.z + sphere.radius_m);
  if (!(top > base_z_m) || !std::isfinite(top) || !(top_fraction > 0)) return false;
  const double threshold = top - top_fraction * (top - base_z_m);
  double x = 0, y = 0;
  int n = 0;
  for (const SurfaceSphere& sphere : snapshot.spheres) {
    if (sphere.position_m.z + sphere.radius_m < threshold) continue;
    x += sphere.position_m.x, y += sphere.position_m.y, ++n;
  }
  *axis_point_m = {x / n, y / n, base_z_m};
  return true;
}

}  // namespace demcal::objectives
