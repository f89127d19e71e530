#pragma once
// Shared helpers of the wall tests: a one-material scene, triangle-mesh walls (a box, a flat
// plate), the Hertz rest overlap of a sphere on a wall and a checked Initialize.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/simulation/simulation.h"
#include "core/walls/triangle_mesh.h"

namespace demcal::core::wall_test {

// One material (glass-like, E = 1e8 Pa, ν = 0.25, ρ = 2500 kg/m³), one species of diameter d,
// rolling model "none", fixed time step.
inline Scene OneMaterialScene(double diameter_m, double friction = 0.5, double restitution = 0.5) {
  Scene s;
  s.materials = {{"glass", 1e8, 0.25, 2500}};
  Species sp;
  sp.name = "sphere";
  sp.size.diameter_m = diameter_m;
  s.species = {sp};
  PairParameters pp;
  pp.sliding_friction = friction;
  pp.restitution = restitution;
  s.pair_parameters = {pp};
  s.rolling.name = "none";
  s.time.timestep_s = 1e-5;
  return s;
}

inline double SphereMass(const Scene& s, double radius_m) {
  return s.materials[0].density_kg_m3 * 4.0 / 3.0 * std::numbers::pi * std::pow(radius_m, 3);
}

// Hertz: F = (4/3) E* sqrt(R) δ^{3/2} (Johnson, Contact Mechanics, 1985, §4.2) with a rigid
// flat; E* = E / (2 (1 − ν²)) for two bodies of the same material.
inline double HertzRestOverlap(const Scene& s, double radius_m, double load_N) {
  const Material& m = s.materials[0];
  const double e_star = m.youngs_modulus_Pa / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
  return std::pow(load_N / (4.0 / 3.0 * e_star * std::sqrt(radius_m)), 2.0 / 3.0);
}

inline std::shared_ptr<const TriangleMesh> MakeMesh(const std::vector<Vec3>& v,
                                                    const std::vector<std::array<int32_t, 3>>& t) {
  std::string error;
  auto mesh = TriangleMesh::FromIndexed(v, t, {}, &error);
  INFO(error);
  REQUIRE(mesh);
  return std::make_shared<const TriangleMesh>(std::move(*mesh));
}

// The closed surface of an axis-aligned box, 12 triangles (the floor's diagonal runs from
// (lo.x, lo.y) to (hi.x, hi.y)); open_top drops the two lid triangles.
inline Wall MeshBox(const std::string& name, const Vec3& lo, const Vec3& hi, bool open_top) {
  std::vector<Vec3> v;
  for (int k = 0; k < 8; ++k)
    v.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  std::vector<std::array<int32_t, 3>> t = {
      {0, 2, 3}, {0, 3, 1},  // z = lo (floor), diagonal 0–3
      {0, 1, 5}, {0, 5, 4},  // y = lo
      {2, 6, 7}, {2, 7, 3},  // y = hi
      {0, 4, 6}, {0, 6, 2},  // x = lo
      {1, 3, 7}, {1, 7, 5},  // x = hi
  };
  if (!open_top) t.insert(t.end(), {{4, 5, 7}, {4, 7, 6}});
  return Wall(name, 0, MeshRef{MakeMesh(v, t), {}, "box"});
}

// A flat square plate z = z0 over [-half, half]², two triangles sharing the diagonal from
// (-half, -half) to (half, half).
inline Wall MeshPlate(const std::string& name, double half, double z0) {
  const std::vector<Vec3> v = {{-half, -half, z0}, {half, -half, z0}, {half, half, z0},
                               {-half, half, z0}};
  return Wall(name, 0, MeshRef{MakeMesh(v, {{0, 1, 2}, {0, 2, 3}}), {}, "plate"});
}

inline void InitializeOrFail(Simulation& sim) {
  std::string error;
  const bool ok = sim.Initialize(&error);
  INFO(error);
  REQUIRE(ok);
}

inline Vec3 TotalWallForce(const Simulation& sim) {
  Vec3 f;
  for (const WallLoad& load : sim.WallLoads()) f += load.force_N;
  return f;
}

}  // namespace demcal::core::wall_test
