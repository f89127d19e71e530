#include "objectives/report/heap_profile_svg.h"

#include <algorithm>
#include <cstdio>

#include "objectives/metrics/surface_profile.h"

namespace demcal::objectives {

namespace {

constexpr double kMm = 1e3;

std::string Degrees(double deg) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f°", deg);
  return buffer;
}

std::string Title(const std::string& kind, const ReposeAngle& angle) {
  if (!angle.ok) return kind + ": not measured (" + angle.message + ")";
  return kind + ": " + Degrees(angle.angle_deg) + " ± " + Degrees(angle.spread_deg) + " over " +
         std::to_string(angle.flanks.size()) + " flank(s)";
}

PlotSeries Dots(const std::vector<SurfacePoint>& points, const std::string& label) {
  PlotSeries dots{.label = label, .color = "#7f7f7f", .dots = true, .width_px = 1.5};
  for (const SurfacePoint& p : points) {
    dots.x.push_back(p.s_m * kMm);
    dots.y.push_back(p.top_m * kMm);
  }
  return dots;
}

// Dashed horizontal lines at the bottom and top of the height window, over [lo, hi] (mm).
void AddWindow(const ReposeAngle& angle, const ReposeAngleOptions& options, double lo, double hi,
               SvgPlot* plot) {
  for (double fraction : {options.window_low, options.window_high}) {
    const double z = (options.base_z_m + fraction * angle.heap_height_m) * kMm;
    plot->series.push_back({.label = fraction == options.window_low ? "height window" : "",
                            .x = {lo, hi},
                            .y = {z, z},
                            .color = "#2ca02c",
                            .dashed = true,
                            .width_px = 1});
  }
}

// The fitted line of one flank over its fitted range; s is drawn at origin + direction·s (mm).
PlotSeries FlankLine(const FlankFit& f, double origin_m, double direction, std::string label,
                     std::string color) {
  PlotSeries line{.label = std::move(label), .color = std::move(color), .width_px = 2};
  for (double s : {f.s_min_m, f.s_max_m}) {
    line.x.push_back((origin_m + direction * s) * kMm);
    line.y.push_back((f.intercept_m + f.slope * s) * kMm);
  }
  return line;
}

struct Extent {
  double lo = 0, hi = 0;  // mm
};

Extent XRange(const std::vector<SurfacePoint>& points) {
  double lo = 0, hi = 0;
  if (!points.empty()) {
    lo = hi = points.front().s_m;
    for (const SurfacePoint& p : points) lo = std::min(lo, p.s_m), hi = std::max(hi, p.s_m);
  }
  return {lo * kMm, hi * kMm};
}

}  // namespace

SvgPlot SlotHeapProfilePlot(const Snapshot& snapshot, const ReposeAngle& angle,
                            const ReposeAngleOptions& options) {
  SvgPlot plot{.title = Title("slot heap", angle),
               .x_label = "x [mm]",
               .y_label = "z [mm]",
               .equal_aspect = true};
  if (!(angle.cell_m > 0)) return plot;
  const std::vector<SurfacePoint> profile = SlotProfile(snapshot, angle.cell_m);
  plot.series.push_back(Dots(profile, "surface points"));
  const Extent x = XRange(profile);
  AddWindow(angle, options, x.lo, x.hi, &plot);
  for (size_t k = 0; k < angle.flanks.size(); ++k) {
    const FlankFit& f = angle.flanks[k];
    const double direction = f.azimuth_deg > 90 ? -1 : 1;  // the left flank points to −x
    plot.series.push_back(FlankLine(f, angle.apex_s_m, direction,
                                    f.label + " " + Degrees(f.angle_deg), SeriesColor(2 * k + 1)));
  }
  return plot;
}

SvgPlot ConicalHeapProfilePlot(const Snapshot& snapshot, Vec3 axis_point_m,
                               const ReposeAngle& angle, const ReposeAngleOptions& options) {
  SvgPlot plot{.title = Title("conical heap", angle),
               .x_label = "distance to the axis r [mm]",
               .y_label = "z [mm]",
               .equal_aspect = true};
  if (!(angle.cell_m > 0) || options.sectors < 1) return plot;
  std::vector<SurfacePoint> all;
  for (const auto& sector : SectorProfiles(snapshot, axis_point_m, options.sectors, angle.cell_m))
    all.insert(all.end(), sector.begin(), sector.end());
  plot.series.push_back(Dots(all, "surface points"));
  const Extent r = XRange(all);
  AddWindow(angle, options, r.lo, r.hi, &plot);
  for (size_t k = 0; k < angle.flanks.size(); ++k)
    plot.series.push_back(
        FlankLine(angle.flanks[k], 0, 1, k == 0 ? "sector fits" : "", SeriesColor(1)));
  return plot;
}

}  // namespace demcal::objectives
