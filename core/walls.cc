#include "core/walls.h"

namespace demcal::core {

std::vector<PlaneWall> BoxInnerFaces(const std::string& name, const Vec3& lo, const Vec3& hi,
                                     int material, bool open_top) {
  std::vector<PlaneWall> faces = {
      {name + ".xmin", lo, {1, 0, 0}, material, {}}, {name + ".xmax", hi, {-1, 0, 0}, material, {}},
      {name + ".ymin", lo, {0, 1, 0}, material, {}}, {name + ".ymax", hi, {0, -1, 0}, material, {}},
      {name + ".zmin", lo, {0, 0, 1}, material, {}},
  };
  if (!open_top) faces.push_back({name + ".zmax", hi, {0, 0, -1}, material, {}});
  return faces;
}

}  // namespace demcal::core
