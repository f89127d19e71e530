#pragma once
// An orientation-averaged size of a clumped grain: its mean caliper diameter (the mean Feret
// diameter of particle sizing), the width between two parallel planes that touch the grain,
// averaged over all directions. For a sphere it is the diameter; for an elongated grain it lies
// between its thickness and its length (a chain of length L and member radius r: about r + L/2,
// Cauchy's formula for a spherocylinder), which makes it the size of a tumbling grain where a
// sieve-equivalent diameter understates an elongated one, e.g. in Beverloo's empty annulus at
// an orifice (experiments/segregation/funnel_geometry.h).
//
// Usage:
//   double w = MeanCaliperDiameter(template.spheres);  // same length unit as the members
#include <vector>

#include "core/bodies/clump_template.h"

namespace demcal::core {

// Mean over directions u of max_k(c_k·u + r_k) − min_k(c_k·u − r_k), by a 4,096-point Fibonacci
// lattice on the unit sphere (deterministic; relative error below 1e-3 on the kinked widths of
// sphere chains). 0 for no members.
double MeanCaliperDiameter(const std::vector<ClumpSphere>& spheres);

}  // namespace demcal::core
