#pragma once
// ClumpTemplate: the shape of a rigid multi-sphere ("clumped sphere") particle, i.e. a union of
// member spheres, together with its mass properties for one density (docs/physics.md §7.1). The
// template is expressed in its own principal frame: centre of mass at the origin and the body
// axes along the principal axes of inertia, sorted so that I1 ≤ I2 ≤ I3 (for an elongated clump
// axis 1 is the long axis). SI units throughout (m, m³, kg, kg·m²).
//
// Mass properties of the union (overlapping volume counted once) are integrated by one of:
//   kExactSum   spheres + parallel-axis theorem; exact when no two spheres overlap, otherwise it
//               counts the overlaps twice (an overestimate: +18.5 % volume for two unit spheres
//               at distance 1, docs/physics.md §7.1).
//   kCollinear  exact (to round-off) for any overlap when all centres lie on one line: the union
//               is a solid of revolution whose squared profile is piecewise one sphere's parabola.
//   kVoxel      regular grid of cubic cells of side r_min / voxel_divisions over the bounding box;
//               a cell counts (as a full uniform cube) when its centre is inside any sphere
//               (woodem SphereClumpGeom::recompute, docs/physics.md §7.1).
//   kMonteCarlo uniform random points in the bounding box; error ∝ N^{-1/2} (seeded).
//   kAuto       kExactSum without overlaps, else kCollinear if collinear, else kVoxel.
//
// Plain value types; the functions are pure and thread-safe (each call owns its data).
//
// Usage:
//   std::vector<ClumpSphere> s = {{{0, 0, 0}, 1e-3}, {{1e-3, 0, 0}, 1e-3}};
//   ClumpTemplate t;
//   std::string err;
//   if (!BuildClumpTemplate(s, 2500.0, {}, &t, &err)) { /* report err */ }
//   t.mass_kg; t.principal_inertia_kg_m2;  // t.spheres are now in the principal frame
#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math/quaternion.h"
#include "core/math/vec3.h"

namespace demcal::core {

// One member sphere of a clump.
struct ClumpSphere {
  Vec3 centre_m;
  double radius_m = 0;
};

enum class MassMethod { kAuto, kExactSum, kCollinear, kVoxel, kMonteCarlo };
const char* MassMethodName(MassMethod method);

struct MassPropertiesOptions {
  MassMethod method = MassMethod::kAuto;
  // Voxel spacing is r_min / voxel_divisions. At 40 the worst lens-volume error over 40 random
  // two-sphere placements is 0.05 % (clump_template_test.cc asserts the required < 0.5 %; an
  // axis-aligned sweep gave 0.19 % at 20 and 0.95 % at 10). Each grid column is summed in closed
  // form, so the cost grows as divisions², milliseconds for typical clumps.
  int voxel_divisions = 40;
  // Refuse voxel grids with more columns (nx·ny) than this instead of running for minutes.
  int64_t max_voxel_columns = 50'000'000;
  int64_t monte_carlo_points = 2'000'000;
  uint64_t seed = 1;  // Monte Carlo only

  // voxel_divisions ≥ 1, max_voxel_columns ≥ 1, monte_carlo_points ≥ 1000.
  bool IsValid(std::string* error) const;
};

// Mass properties of a union of spheres in the frame the spheres were given in.
struct MassProperties {
  double volume_m3 = 0;
  double mass_kg = 0;
  Vec3 centre_of_mass_m;
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about the centre of mass
  MassMethod method_used = MassMethod::kAuto;
  int64_t samples = 0;  // voxel cells inside, Monte Carlo points drawn; 0 for exact methods
};

// Computes the union's mass properties. Returns false with a message naming the offending entry
// on: empty list, non-finite centre, radius not finite or ≤ 0, density not finite or ≤ 0, bad
// options, kCollinear requested for non-collinear centres, a voxel grid over the column limit,
// or a zero integrated volume.
bool ComputeMassProperties(const std::vector<ClumpSphere>& spheres, double density_kg_m3,
                           const MassPropertiesOptions& options, MassProperties* out,
                           std::string* error);

// Shape descriptors of a bounding box with sorted edge lengths L ≥ I ≥ S (Zingg-style).
struct AspectRatios {
  double elongation = 1;       // I / L ≤ 1
  double flatness = 1;         // S / I ≤ 1
  double long_over_short = 1;  // L / S ≥ 1
};
AspectRatios AspectRatiosFromExtents(const Vec3& extents_m);

struct ClumpTemplate {
  std::vector<ClumpSphere> spheres;  // principal frame, centre of mass at the origin
  double density_kg_m3 = 0;
  double volume_m3 = 0;  // union volume
  double mass_kg = 0;
  Vec3 principal_inertia_kg_m2;  // (I1, I2, I3), ascending, about the centre of mass
  MassMethod method_used = MassMethod::kAuto;
  // Where the principal frame sits in the frame the spheres were given in:
  //   x_input = input_centre_of_mass_m + Rotate(input_from_principal, x_principal).
  Vec3 input_centre_of_mass_m;
  Quaternion input_from_principal;

  // Diameter of the sphere with the same volume, (6V/π)^{1/3}.
  double EquivalentVolumeDiameter() const;
  // max_k |c_k| + r_k: radius of the smallest origin-centred sphere enclosing the clump.
  double BoundingRadius() const;
  // Edge lengths of the bounding box along the principal axes (1, 2, 3).
  Vec3 BoundingBoxExtents() const;
  AspectRatios ShapeAspectRatios() const { return AspectRatiosFromExtents(BoundingBoxExtents()); }
};

// Principal moments (ascending) and axes of a symmetric inertia tensor. Column i of *axes is
// principal axis i in the tensor's frame; the matrix is a proper rotation (det = +1), and the sign
// of axes 1 and 2 is fixed (largest component positive) so results are reproducible.
bool PrincipalFrame(const Eigen::Matrix3d& inertia, Vec3* moments, Eigen::Matrix3d* axes);

// Computes the mass properties of `spheres` (any frame) and returns the template re-expressed in
// its principal frame, plus the transform back to the input frame. Principal axes of degenerate
// moments (spheres, symmetric tops) are any orthonormal basis of the degenerate subspace.
bool BuildClumpTemplate(const std::vector<ClumpSphere>& spheres, double density_kg_m3,
                        const MassPropertiesOptions& options, ClumpTemplate* out,
                        std::string* error);

}  // namespace demcal::core
