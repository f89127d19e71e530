#pragma once
// A species' clump shape at unit size. Scene files give a clump's member spheres in any length
// unit and frame (core/materials/material.h, ShapeSphere); the engine places a grain of diameter
// d as the members scaled so that their union's equivalent-volume diameter is d. The scaling
// lives here so that everything sized from a grain (the placed template, the time step from the
// smallest member) reads one normalisation.
#include <string>
#include <vector>

#include "core/bodies/clump_template.h"
#include "core/materials/material.h"

namespace demcal::core {

// The members of `shape` scaled to unit equivalent-volume diameter (union volume π/6). False,
// with the reason in *error, when the members do not make a clump (BuildClumpTemplate's checks).
bool UnitDiameterClumpMembers(const std::vector<ShapeSphere>& shape,
                              std::vector<ClumpSphere>* members, std::string* error);

// The clump template (unit density) of `shape` at unit equivalent-volume diameter: the members
// above, in their principal frame. False, with the reason in *error, as above.
bool UnitDiameterClumpTemplate(const std::vector<ShapeSphere>& shape, ClumpTemplate* out,
                               std::string* error);

}  // namespace demcal::core
