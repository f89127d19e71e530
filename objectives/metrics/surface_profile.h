#pragma once
// Surface profile of a heap: the free surface as one point per cell along a horizontal
// coordinate s (x for a slot heap, distance to the axis for a sector of a conical heap). Each
// point is the top z + R of the highest sphere whose centre falls in the cell, at that sphere's
// own s (not the cell centre), so points on a flat-faced packing lie exactly on its face.
// Recipe: docs/physics.md §5.1 step 1.
//
//   std::vector<SurfacePoint> profile = SlotProfile(snapshot, /*cell_m=*/0.003);
#include <vector>

#include "objectives/common/snapshot.h"

namespace demcal::objectives {

struct SurfacePoint {
  double s_m = 0;    // horizontal coordinate of the sphere centre
  double top_m = 0;  // z of the sphere's top, z + R
};

// Slot (pseudo-2D) heap: s = x, the depth y collapsed; cells start at the smallest sphere x.
std::vector<SurfacePoint> SlotProfile(const Snapshot& snapshot, double cell_m);

// Conical heap: one profile per azimuthal sector around the vertical axis through axis_point_m
// (its z ignored); s = distance to the axis. Cells are rings of width cell_m from the axis, split
// into arcs about cell_m long so that cells far out are no larger than near the axis. Sector k
// spans azimuths [k, k + 1)·360°/sectors from +x towards +y.
std::vector<std::vector<SurfacePoint>> SectorProfiles(const Snapshot& snapshot, Vec3 axis_point_m,
                                                      int sectors, double cell_m);

// Index of the apex of a profile: the highest point within one neighbour of the maximum of the
// 3-point moving average, so a single high outlier away from the peak does not move the apex but
// an exact profile keeps its true peak. -1 for an empty profile.
int ApexIndex(const std::vector<SurfacePoint>& profile);

}  // namespace demcal::objectives
