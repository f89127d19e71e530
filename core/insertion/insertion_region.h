#pragma once
// InsertionRegion: where new particles may be placed — an axis-aligned box or a vertical
// (z-axis) cylinder. Sample() draws a centre that keeps a sphere of radius r wholly inside.
#include "core/math/random.h"
#include "core/math/vec3.h"

namespace demcal::core {

struct InsertionRegion {
  enum class Shape { kBox, kCylinder };
  Shape shape = Shape::kBox;
  Vec3 min_m, max_m;       // box corners; for a cylinder, z range in min_m.z / max_m.z
  Vec3 axis_point_m;       // cylinder: a point on its vertical axis (x, y used)
  double radius_m = 0;     // cylinder radius

  static InsertionRegion Box(const Vec3& lo, const Vec3& hi) { return {Shape::kBox, lo, hi, {}, 0}; }
  static InsertionRegion Cylinder(const Vec3& axis_point, double radius, double z_lo, double z_hi) {
    return {Shape::kCylinder,
            {axis_point.x - radius, axis_point.y - radius, z_lo},
            {axis_point.x + radius, axis_point.y + radius, z_hi},
            axis_point,
            radius};
  }

  double Volume() const {
    const Vec3 e = max_m - min_m;
    return shape == Shape::kBox ? e.x * e.y * e.z : 3.14159265358979323846 * radius_m * radius_m * e.z;
  }
  // Smallest dimension: a sphere wider than this cannot be placed.
  double MinExtent() const {
    const Vec3 e = max_m - min_m;
    return e.x < e.y ? (e.x < e.z ? e.x : e.z) : (e.y < e.z ? e.y : e.z);
  }

  // A uniformly distributed centre keeping the sphere (radius r) inside; false if it cannot fit.
  bool Sample(double r, Rng& rng, Vec3* x) const {
    if (2 * r >= MinExtent()) return false;
    x->z = rng.Uniform(min_m.z + r, max_m.z - r);
    if (shape == Shape::kBox) {
      x->x = rng.Uniform(min_m.x + r, max_m.x - r);
      x->y = rng.Uniform(min_m.y + r, max_m.y - r);
      return true;
    }
    const double rr = radius_m - r;  // rejection sampling in the enclosing square
    for (;;) {
      const double u = rng.Uniform(-rr, rr), v = rng.Uniform(-rr, rr);
      if (u * u + v * v <= rr * rr) {
        x->x = axis_point_m.x + u;
        x->y = axis_point_m.y + v;
        return true;
      }
    }
  }
};

}  // namespace demcal::core
