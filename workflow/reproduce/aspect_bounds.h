#pragma once
// The range of aspect ratios a of the prolate spheroid [a, 1, 1] over which an n-sphere chain
// (core::ApproximateEllipsoid) is a grain worth calibrating, per sphere count n >= 2:
//  - upper bound, ConnectedAspectLimit: the longest chain whose spheres still touch (2 for 2
//    spheres, 3 for 3; 4 and 5 spheres stay connected beyond 3.5). Past it the chain is a rigid
//    dumbbell with a gap, not a grain.
//  - lower bound, DistinctAspectLimit: the shortest chain whose neighbouring sphere centres stand
//    at least kMinMemberSpacing of the smaller radius apart. Towards a = 1 the chain closes onto
//    one sphere (at a = 1 all n spheres coincide): a contact then presses on several members at
//    almost the same overlap, n against a wall and up to n² against another such grain, on the
//    mass of one sphere. The run ends non_finite; the shape is count 1's sphere anyway.
// Why 0.15: measured on examples/aor_bp.json with the species a clump, at its quick fidelity
// (Rayleigh fraction 0.25), replicate 0 of seed 2018 or, where "3 of 3", replicates 0-2; the
// spacing in member radii in brackets:
//   2 spheres: a = 1, 1.001, 1.01 (0, 0.003, 0.027) end non-finite, 1.005 (0.013) loses a grain;
//     1.02 (0.053) gives a heap, 1.038 (0.101) and 1.1 (0.26) 3 of 3;
//   3 spheres: a = 1.03, 1.067 (0.045, 0.100) end non-finite; 1.1 (0.150), 1.2 (0.30) 3 of 3;
//   4 spheres: a = 1.05 (0.044) ends non-finite; 1.115 (0.115), 1.5 (0.51) 3 of 3.
// 0.15 is half as much again as the largest spacing that failed; the bounds are a = 1.057,
// 1.100, 1.163 and 1.191 for 2-5 spheres. The 2-sphere chains at a = 1 and 1.001 give a heap at
// a quarter of the time step. These were measured with the time step of the grain's
// equivalent sphere; with it 5-sphere heaps also ended non-finite at a = 1.5 (2 of 3, spacing
// 0.36) and 2.0 (1 of 3), and with the Rayleigh time of the smallest member sphere, which the
// engine now takes (core/scene/scene.cc), both gave heaps 3 of 3: the bounds are conservative.
// The engine's own step rule for members that nearly coincide (core/bodies/contact_multiplicity.h)
// shortens the step of the shortest chains searched to 0.40-0.62 of their members'.
// The workflow file is checked against both bounds (workflow_file.cc); the search uses them as
// each count's bracket (shape_search.h). Scale-free: the chain is normalised to the species' size.
//
//   double lo = DistinctAspectLimit(2, 1.0, 3.5);    // 1.057
//   double hi = ConnectedAspectLimit(2, 1.0, 3.5);   // 2
#include <string>

namespace demcal::workflow {

// Neighbouring sphere centres of a chain at least this fraction of the smaller radius apart.
inline constexpr double kMinMemberSpacing = 0.15;

// The smallest spacing of neighbouring sphere centres of `count` spheres chained on [aspect, 1, 1]
// over the smaller radius of each pair (infinity for count < 2; 0 where the chain is refused).
double MinMemberSpacing(int count, double aspect);

// The largest aspect ratio in [min, max] at which `count` spheres chained on [a, 1, 1] still
// touch (max for count < 2; min if none does).
double ConnectedAspectLimit(int count, double min, double max);

// The smallest aspect ratio in [min, max] at which `count` spheres chained on [a, 1, 1] stand
// kMinMemberSpacing apart; the spacing grows as the chain stretches (min for count < 2; max if
// none does).
double DistinctAspectLimit(int count, double min, double max);

}  // namespace demcal::workflow
