#pragma once
// Constructed heaps with a known surface slope for the repose-angle tests: surface spheres whose
// tops lie on the flank line (tops, not centres, so the profile of surface_profile.h samples the
// line exactly), interior filler well below the surface and a flat one-layer run-out beyond the
// toe. Optional noise: Gaussian jitter of every position and uniform random radii.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "objectives/common/snapshot.h"

namespace demcal::objectives::testing {

struct HeapNoise {
  double position_sigma_m = 0;  // Gaussian jitter of x, y, z
  double radius_fraction = 0;   // radius uniform in R·[1 − f, 1 + f]
  unsigned seed = 1;
};

// Vertical standard deviation of a surface top under the noise, on a flank of slope angle θ:
// z jitter, x jitter seen through the slope, and the radius spread (uniform: width/√12).
inline double SurfaceNoiseSigma(const HeapNoise& n, double radius_m, double angle_deg) {
  const double t = std::tan(angle_deg * std::numbers::pi / 180);
  const double radius_sigma = 2 * n.radius_fraction * radius_m / std::sqrt(12.0);
  return std::sqrt(n.position_sigma_m * n.position_sigma_m * (1 + t * t) +
                   radius_sigma * radius_sigma);
}

class HeapBuilder {
 public:
  HeapBuilder(double diameter_m, const HeapNoise& noise)
      : radius_(diameter_m / 2), noise_(noise), rng_(noise.seed) {}

  // A sphere of the nominal radius centred so that its nominal top is at `top_m`.
  void AddTop(double x, double y, double top_m) {
    std::normal_distribution<double> jitter(0, noise_.position_sigma_m);
    std::uniform_real_distribution<double> scale(1 - noise_.radius_fraction,
                                                 1 + noise_.radius_fraction);
    const double r = noise_.radius_fraction > 0 ? radius_ * scale(rng_) : radius_;
    Vec3 c{x, y, top_m - radius_};
    if (noise_.position_sigma_m > 0) c += Vec3{jitter(rng_), jitter(rng_), jitter(rng_)};
    snap_.spheres.push_back({c, r, static_cast<int>(snap_.grains.size())});
    snap_.grains.push_back({static_cast<int64_t>(snap_.grains.size()), 0, c, {}, r, 1e-5});
  }
  double radius() const { return radius_; }
  const Snapshot& snapshot() const { return snap_; }

 private:
  double radius_;
  HeapNoise noise_;
  std::mt19937 rng_;
  Snapshot snap_;
};

struct SlotHeapShape {
  double apex_x_m = 0;
  double height_m = 0.04;  // apex top above the floor z = 0
  double left_deg = 30, right_deg = 30;
  double half_width_m = 0.1;  // profile from apex − w to apex + w (run-out beyond the toes)
  double x_min_m = -1e9;      // a wall: nothing left of it
  int depth_layers = 3;       // copies along y, one diameter apart
  double top_cut_m = 0;       // > 0: the crest flattened this far below the apex (a rounded top)
};

// Pseudo-2D triangle heap on the floor z = 0: surface spheres every half diameter along x.
inline Snapshot SlotHeap(const SlotHeapShape& shape, double diameter_m, const HeapNoise& noise) {
  HeapBuilder b(diameter_m, noise);
  const double step = diameter_m / 2;
  const int n = static_cast<int>(std::round(shape.half_width_m / step));
  for (int i = -n; i <= n; ++i) {
    const double x = shape.apex_x_m + i * step;
    if (x < shape.x_min_m) continue;
    const double deg = i < 0 ? shape.left_deg : shape.right_deg;
    const double line =
        shape.height_m - std::tan(deg * std::numbers::pi / 180) * std::abs(i * step);
    const double top = std::max(std::min(line, shape.height_m - shape.top_cut_m),
                                diameter_m);  // the run-out: one layer on the floor
    for (int layer = 0; layer < shape.depth_layers; ++layer) {
      const double y = layer * diameter_m;
      b.AddTop(x, y, top);
      if (i % 2 == 0)  // filler at least two diameters below the surface
        for (double fill = diameter_m; fill < top - 2 * diameter_m; fill += diameter_m)
          b.AddTop(x, y, fill);
    }
  }
  return b.snapshot();
}

// Conical heap around the vertical axis through (axis_x, axis_y): rings every half diameter,
// spheres about half a diameter apart on each ring; tops on top = H − tanθ·r.
inline Snapshot ConicalHeap(double axis_x, double axis_y, double height_m, double angle_deg,
                            double diameter_m, const HeapNoise& noise) {
  HeapBuilder b(diameter_m, noise);
  const double step = diameter_m / 2;
  const double slope = std::tan(angle_deg * std::numbers::pi / 180);
  const int rings = static_cast<int>(height_m / slope / step) + 4;
  for (int j = 0; j <= rings; ++j) {
    const double r = j * step;
    const int around = std::max(1, static_cast<int>(std::round(2 * std::numbers::pi * r / step)));
    for (int k = 0; k < around; ++k) {
      const double phi = 2 * std::numbers::pi * (k + 0.5 * (j % 2)) / around;
      b.AddTop(axis_x + r * std::cos(phi), axis_y + r * std::sin(phi),
               std::max(height_m - slope * r, diameter_m));
    }
  }
  return b.snapshot();
}

}  // namespace demcal::objectives::testing
