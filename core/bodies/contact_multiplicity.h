#pragma once
// How much a clump shape shortens the stable time step below its smallest member's Rayleigh
// time (docs/physics.md §1.5).
//
// The Rayleigh time of one member sphere assumes one contact spring on one sphere's mass. Members
// that nearly coincide (a chain close to a sphere, members of a tomogram shape nested in one
// another) touch a partner at almost one point: k members press with k springs in parallel
// against a wall, and up to k² member pairs between two such grains, on the mass of about one
// sphere. The contact then rings √k to k times faster than one member's, and the explicit step
// that suits the member blows up. Measured on rig 3 of the cross-engine datasets (3-sphere chains
// of aspect 1.05): energy_blow_up by t = 0.06 s at 0.2 Δt_R, and without friction the same grains
// run; the tangential springs, stiffer still against a grain's rotation, go first.
// The rule is a bound on springs and mass, not an eigenvalue analysis: it ignores the members'
// stiffness differences (the smallest member's Rayleigh time already bounds them) and, between
// two species, takes each species' own k².
//
// The rule. Two members i and j touch a common tangent plane at points
// s_ij = √(d_ij² − (r_i − r_j)²) apart (d_ij the distance of their centres); a member inside
// another never touches. Member j adds w_ij = max(0, 1 − s_ij / (kCoincidentSpacing r_ij)) to the
// springs at i's contact point (r_ij the smaller radius, w_ii = 1), and k = max_i Σ_j w_ij is the
// most springs at one point. Between two grains of the shape, k² springs act on the pair's
// reduced mass M/2 where two lone members have one spring on m/2, so the step scales by
// √(M/m) / k, with M the clump's mass and m its smallest member's; never above 1 (a clump is
// never given a longer step than its smallest member).
#include <vector>

#include "core/bodies/clump_template.h"

namespace demcal::core {

// Tangent points closer than this many of the smaller member radius count as one point (the
// weight falls linearly to 0 there). Two members a distance s apart both press on a partner of
// their size once the overlap δ exceeds the gap s²/(4r) the second one stands back, i.e. within
// s < 2√(rδ), the contact patch's diameter. 0.5 is that diameter at δ = 6 % of r, the overlap of
// a 1 m/s impact at the soft stiffness (×0.01) of the quick fidelities. Measured on rig 3
// (docs/physics.md §1.5): 3-sphere chains with members 0.26-0.31 radii apart ended non_finite
// at their members' step and ran at half of it; a 0.3 cut-off left them unstable.
inline constexpr double kCoincidentSpacing = 0.5;

// The most member springs that act at one contact point of the clump `members` (any frame and
// size): 1 for a sphere or for members apart by kCoincidentSpacing or more, up to n for n
// coincident members.
double ContactMultiplicity(const std::vector<ClumpSphere>& members);

// The factor in (0, 1] on the smallest member's Rayleigh time: min(1, √(M/m) / k), where
// `union_volume_m3` is the members' union volume (M/m = V / ((4/3)π r_min³) at one density).
double ClumpStepFactor(const std::vector<ClumpSphere>& members, double union_volume_m3);

}  // namespace demcal::core
