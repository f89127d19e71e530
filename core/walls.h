#pragma once
// Walls from primitives. Core I has infinite planes; a box is its six inner faces. Every wall
// has a material (for the interaction table) and may translate with a prescribed velocity.
// A sphere touches a plane when its centre is closer than its radius on the inner side.
#include <string>
#include <vector>

#include "core/vec3.h"

namespace demcal::core {

struct PlaneWall {
  std::string name;
  Vec3 point_m;         // any point on the plane
  Vec3 normal;          // unit normal pointing into the region where particles live
  int material = 0;
  Vec3 velocity_m_s;    // prescribed translation (zero = fixed)
};

// The six inner faces of an axis-aligned box (a closed container), named name.xmin ... name.zmax.
std::vector<PlaneWall> BoxInnerFaces(const std::string& name, const Vec3& min_m, const Vec3& max_m,
                                     int material, bool open_top);

}  // namespace demcal::core
