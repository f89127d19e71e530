#pragma once
// Clump shape generators: n-sphere (n = 1..5) approximations of ellipsoids, and of closed
// triangle meshes (STL particle shapes) through their inertia-equivalent ellipsoid. Spheres come
// out in the target's principal frame (long axis = x, centre of mass at the origin), ready for
// BuildClumpTemplate. SI units (m, m³). Pure functions, thread-safe.
//
// Every approximation reports how well it matches the target: union volume (integrated exactly,
// MassMethod::kCollinear) against the target volume, and the bounding-box aspect ratios against
// the target's. The clump is a chain of spheres on the long axis, hence axisymmetric: it cannot
// reproduce b ≠ c, and that shows up in the reported aspect-ratio error.
//
// Usage:
//   ShapeApproximation s;
//   std::string err;
//   if (!ApproximateEllipsoid({2e-3, 1e-3, 1e-3}, 3, &s, &err)) { /* report err */ }
//   s.volume_error;  // ~1e-13; s.aspect_ratio_error: relative error of L/S
//   ClumpTemplate t;
//   BuildClumpTemplate(s.spheres, 2500.0, {}, &t, &err);
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "core/bodies/clump_template.h"
#include "core/math/quaternion.h"
#include "core/math/vec3.h"

namespace demcal::core {

// A sphere-chain approximation of a target shape and its errors against the target.
struct ShapeApproximation {
  std::vector<ClumpSphere> spheres;  // target principal frame, centres on the x axis
  double target_volume_m3 = 0;
  double clump_volume_m3 = 0;  // exact union volume
  double volume_error = 0;     // (clump − target) / target
  Vec3 target_extents_m;       // target bounding box along the principal axes
  Vec3 clump_extents_m;
  AspectRatios target_ratios, clump_ratios;
  double aspect_ratio_error = 0;  // (clump L/S) / (target L/S) − 1
  // Whether consecutive spheres overlap or touch. Too few spheres for an elongated target leave
  // gaps (e.g. 2 spheres for a 3:1 spheroid); the clump is still rigid but shaped like a dumbbell.
  bool connected = true;
  // "tapered" (volume, length and width matched), "uniform" (fallback: equal spheres, volume and
  // length matched) or "single" (n = 1: equal-volume sphere).
  std::string construction;
};

// The most spheres ApproximateEllipsoid chains into one shape.
inline constexpr int kMaxEllipsoidSpheres = 5;

// Whether semi-axes [a, b, c] are ones the builder is meaningful for: a >= b >= c, each within
// limits::kClumpLength and a/c within limits::kClumpAspectRatio (core/limits/physical_limits.h,
// with the reasons). False with the problem in *error ("must be ...", "... is outside ...").
bool CheckEllipsoidSemiAxes(const Vec3& semi_axes, std::string* error);

// Approximates the ellipsoid with semi-axes a ≥ b ≥ c > 0 (along x, y, z) by n = 1..5 spheres on
// the x axis whose union has exactly the ellipsoid's volume. See clump_shapes.cc for the
// construction. Errors: n out of range, semi-axes refused by CheckEllipsoidSemiAxes.
bool ApproximateEllipsoid(const Vec3& semi_axes_m, int n_spheres, ShapeApproximation* out,
                          std::string* error);

// A surface triangle; vertices counter-clockwise seen from outside (outward normal by the
// right-hand rule). Inverted meshes (all triangles clockwise) are accepted and flagged.
using Triangle = std::array<Vec3, 3>;

// Mass properties of the solid bounded by a closed triangle mesh, from the divergence theorem:
// the solid is the signed sum of the tetrahedra (p, v0, v1, v2) over the triangles, each with
// closed-form volume, first and second moments (Tonon, J. Math. Stat. 1(1) 2004; the covariance
// form ∫xxᵀdV = det/120 · (Σ v_i v_iᵀ + s sᵀ), s = Σ v_i, for a tetrahedron with a vertex at p).
struct MeshMassProperties {
  double volume_m3 = 0;
  double mass_kg = 0;
  Vec3 centroid_m;
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about the centroid, mesh frame
  Vec3 principal_inertia_kg_m2;                             // ascending
  // Principal frame in the mesh frame: x_mesh = centroid_m + Rotate(mesh_from_principal, x_p).
  Quaternion mesh_from_principal;
  Vec3 principal_extents_m;  // bounding box of the vertices along the principal axes
  // Semi-axes (a ≥ b ≥ c) of the solid ellipsoid with the same principal moments per unit mass,
  // a² = 5 (I2 + I3 − I1) / (2m) etc., then scaled by a common factor to the mesh volume.
  Vec3 equivalent_semi_axes_m;
  bool inverted = false;  // triangles were clockwise (negative signed volume); signs corrected
};

// Errors: empty list, non-finite vertex, density ≤ 0, zero volume, or an open mesh (the
// area-weighted normals do not sum to zero, relative tolerance 1e-8).
bool ComputeMeshMassProperties(const std::vector<Triangle>& triangles, double density_kg_m3,
                               MeshMassProperties* out, std::string* error);

struct MeshApproximation {
  MeshMassProperties mesh;  // computed with density 1 kg/m³
  // Spheres in the mesh principal frame; volume and aspect-ratio errors are against the mesh
  // (its volume and its principal-frame bounding box), not against the intermediate ellipsoid.
  ShapeApproximation shape;
};

// STL particle shape → n spheres: mesh mass properties, equivalent ellipsoid, ApproximateEllipsoid.
bool ApproximateMesh(const std::vector<Triangle>& triangles, int n_spheres, MeshApproximation* out,
                     std::string* error);

}  // namespace demcal::core
