#include "objectives/report/heap_face_svg.h"

#include <algorithm>

#include "objectives/report/svg_canvas.h"

namespace demcal::objectives {
namespace {

constexpr double kMarginPx = 20;

// The spheres to draw: members of grains whose centre lies in the layer range.
std::vector<SurfaceSphere> SpheresInLayers(const Snapshot& snapshot, const HeapBinGrid& grid,
                                           const LayerRange& layers) {
  auto in_range = [&](const Grain& g) {
    const int layer = grid.LayerOf(g.position_m.y);
    return layer >= layers.first && layer <= layers.last;
  };
  std::vector<SurfaceSphere> spheres;
  if (snapshot.spheres.empty()) {
    for (size_t i = 0; i < snapshot.grains.size(); ++i) {
      const Grain& g = snapshot.grains[i];
      if (in_range(g)) spheres.push_back({g.position_m, g.radius_m, static_cast<int>(i)});
    }
  } else {
    for (const SurfaceSphere& s : snapshot.spheres)
      if (in_range(snapshot.grains[s.grain])) spheres.push_back(s);
  }
  // Farthest from the front face first, so nearer spheres cover them.
  std::sort(spheres.begin(), spheres.end(), [](const SurfaceSphere& a, const SurfaceSphere& b) {
    return a.position_m.y > b.position_m.y;
  });
  return spheres;
}

SvgCanvas DrawHeapFace(const Snapshot& snapshot, const HeapBinGrid& grid,
                       const HeapFaceSvgOptions& options) {
  const HeapExtent& e = grid.extent();
  const double width_m = e.x_right_m - e.x_left_m;
  const double scale = (options.width_px - 2 * kMarginPx) / width_m;  // px per metre
  const double height_px = e.height_m * scale + 2 * kMarginPx;
  const LinearMap px_x{e.x_left_m, e.x_right_m, kMarginPx, options.width_px - kMarginPx};
  const LinearMap px_z{e.z_base_m, e.z_base_m + e.height_m, height_px - kMarginPx, kMarginPx};
  SvgCanvas svg(options.width_px, height_px);
  for (const SurfaceSphere& s : SpheresInLayers(snapshot, grid, options.layers)) {
    const int species = snapshot.grains[s.grain].species;
    const bool known = species >= 0 && species < static_cast<int>(options.species_colours.size());
    svg.Circle(px_x(s.position_m.x), px_z(s.position_m.z), s.radius_m * scale,
               known ? options.species_colours[species] : "black", options.outline_colour, 0.3);
  }
  if (options.draw_grid) {
    for (const FaceBin& bin : grid.face_bins()) {
      svg.Rect(px_x(bin.x_min_m), px_z(bin.z_max_m), (bin.x_max_m - bin.x_min_m) * scale,
               (bin.z_max_m - bin.z_min_m) * scale, "none", "black", 1);
    }
  }
  svg.Text(kMarginPx, kMarginPx - 5, "heap face: " + options.layers.name, 12);
  return svg;
}

}  // namespace

std::string HeapFaceSvg(const Snapshot& snapshot, const HeapBinGrid& grid,
                        const HeapFaceSvgOptions& options) {
  return DrawHeapFace(snapshot, grid, options).Document();
}

bool WriteHeapFaceSvg(const std::string& path, const Snapshot& snapshot, const HeapBinGrid& grid,
                      const HeapFaceSvgOptions& options, std::string* error) {
  return DrawHeapFace(snapshot, grid, options).WriteFile(path, error);
}

}  // namespace demcal::objectives
