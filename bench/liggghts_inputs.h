#pragma once
// The LIGGGHTS side of a demcal_bench case from the very particles demcal placed: a data file
// (atom_style granular; type 1 moving spheres, type 2 fixed ones if any; velocities included) and a
// "-var NAME VALUE" list, so both codes start from the same state at any particle count.
#include <string>
#include <utility>
#include <vector>

#include "core/bodies/particles.h"
#include "core/math/vec3.h"

namespace demcal::bench {

using LiggghtsVars = std::vector<std::pair<std::string, double>>;

// Writes DIR/initial.data (the particles in the box [lo, hi], m) and DIR/case.vars (one
// "NAME VALUE" pair per line, SI units). False with a message naming the file on failure.
bool WriteLiggghtsInputs(const std::string& dir, const core::Particles& particles,
                         const core::Vec3& lo_m, const core::Vec3& hi_m, const LiggghtsVars& vars,
                         std::string* error);

}  // namespace demcal::bench
