#pragma once
// The walls of a scene in a LIGGGHTS-PUBLIC 3.8 deck (docs/export.md):
//  - an axis-aligned plane: `fix wall/gran ... primitive type T xplane|yplane|zplane c`;
//  - an infinite cylinder along x, y or z: `primitive type T xcylinder|ycylinder|zcylinder r c1
//  c2`;
//  - anything else (a finite cylinder, a cone frustum such as a funnel, a triangle mesh): an ASCII
//    STL file meshes/<wall>.stl (cylinders and cones cut into kMeshSegments facets around) read
//    by `fix mesh/surface`; all of them touched through one `fix meshes ... wall/gran ... mesh`
//    (LIGGGHTS allows one mesh wall fix).
// Type T = demcal material index + 1. LIGGGHTS' primitive walls and meshes are two-sided.
// A wall removed at a time (a plug) gets an `unfix` there (LiggghtsWallSet::removals).
// Refused (false with *error naming the wall): moving walls, oblique planes, a mesh wall taken
// away during the run.
#include <string>
#include <utility>
#include <vector>

#include "core/scene/scene.h"

namespace demcal::workflow {

inline constexpr int kMeshSegments = 72;

struct LiggghtsWallSet {
  std::string commands;                                        // mesh/surface and wall/gran fixes
  std::vector<std::pair<std::string, std::string>> stl_files;  // (relative path, contents)
  std::vector<std::pair<double, std::string>> removals;        // (time s, fix ids to unfix)
  std::vector<int> materials;                                  // the walls' materials (indices)
  std::vector<std::string> fix_ids;  // per wall: its fix ("w3"; a mesh: its mesh/surface fix)
};

// `law` is the granular model string (LiggghtsLaw::model).
bool LiggghtsWalls(const core::Scene& scene, const std::string& law, LiggghtsWallSet* out,
                   std::string* error);

}  // namespace demcal::workflow
