// The "cdt_relative" rolling slot (LIGGGHTS' rolling_friction cdt, docs/physics.md §2.1) on
// hand-made contacts, against its defining formula:
//   M = μ_r F_n R* ω_r/|ω_r| without its n̂ part, ω_r = ω_i − ω_j;  τ_i = −M, τ_j = +M.
#include <catch2/catch.hpp>

#include "core/contact/rolling_cdt.h"
#include "core/contact/rolling_cdt_relative.h"

using namespace demcal::core;

namespace {

constexpr double kMuR = 0.2, kLoad = 2.0;  // μ_r, elastic normal load (N)

// Grains of radii 1 and 3 mm touching along z: R* = 0.75 mm.
ContactGeometry Pair(const Vec3& omega_i, const Vec3& omega_j) {
  ContactGeometry g;
  g.normal = {0, 0, 1};
  g.radius_i_m = 1e-3;
  g.radius_j_m = 3e-3;
  g.rolling_lever_i_m = 1e-3;
  g.rolling_lever_j_m = 3e-3;
  g.effective_radius_m = 0.75e-3;
  g.omega_i = omega_i;
  g.omega_j = omega_j;
  return g;
}

template <class Law>
ContactResult Apply(const ContactGeometry& g) {
  ResolvedPair p;
  p.rolling_friction = kMuR;
  NormalForce n;
  n.elastic_N = n.total_N = n.rolling_load_N = kLoad;
  ContactHistory h;
  ContactResult r;
  Law{}.Apply(g, p, n, 1e-6, h, r);
  return r;
}

void CheckVec(const Vec3& got, const Vec3& want) {
  INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", "
               << want.y << ", " << want.z << ")");
  CHECK(got.x == Approx(want.x).margin(1e-15));
  CHECK(got.y == Approx(want.y).margin(1e-15));
  CHECK(got.z == Approx(want.z).margin(1e-15));
}

}  // namespace

TEST_CASE("cdt_relative: μr Fn R* against the relative rotation, equal and opposite on the pair",
          "[unit][contact]") {
  // ω_r = (0, 10, 0) − (0, −5, 0) = (0, 15, 0): |M| = 0.2 × 2 N × 0.75 mm = 3e-4 N m along −y on
  // i, +y on j, whatever the spins' sizes (a constant torque).
  const ContactResult r = Apply<RollingCdtRelative>(Pair({0, 10, 0}, {0, -5, 0}));
  const double m = kMuR * kLoad * 0.75e-3;
  CheckVec(r.torque_i, {0, -m, 0});
  CheckVec(r.torque_j, {0, m, 0});
}

TEST_CASE("cdt_relative: no torque when the pair rotates together; EDEM's cdt brakes both",
          "[unit][contact]") {
  // Two grains spinning alike (a rigid pair rolling together) have no relative rotation, so
  // LIGGGHTS' law applies nothing; demcal's "cdt" brakes each grain's own spin with μr Fn R_i.
  const Vec3 spin{1, -2, 0.5};
  const ContactResult relative = Apply<RollingCdtRelative>(Pair(spin, spin));
  CheckVec(relative.torque_i, {});
  CheckVec(relative.torque_j, {});
  const ContactResult own = Apply<RollingCdt>(Pair(spin, spin));
  CHECK(Norm(own.torque_i) == Approx(kMuR * kLoad * 1e-3));
  CHECK(Norm(own.torque_j) == Approx(kMuR * kLoad * 3e-3));
}

TEST_CASE("cdt_relative: the torsion part is removed after the direction is taken",
          "[unit][contact]") {
  // ω_r = (0, 3, 4) with n̂ = z: direction (0, 0.6, 0.8), its normal part dropped, so the
  // torque is 0.6 μr Fn R* along y (LIGGGHTS normalises by the whole |ω_r|).
  const ContactResult r = Apply<RollingCdtRelative>(Pair({0, 3, 4}, {}));
  const double m = 0.6 * kMuR * kLoad * 0.75e-3;
  CheckVec(r.torque_i, {0, -m, 0});
  CheckVec(r.torque_j, {0, m, 0});
}

TEST_CASE("cdt_relative: against a wall it is μr Fn R_i against the grain's spin",
          "[unit][contact]") {
  // A wall has ω = 0 and the kernel gives R* = R_i there, so the law equals EDEM's on a wall.
  ContactGeometry g = Pair({0, 0, 0}, {});
  g.radius_j_m = 0;
  g.effective_radius_m = g.radius_i_m;
  g.omega_i = {-7, 0, 0};
  const ContactResult relative = Apply<RollingCdtRelative>(g);
  const ContactResult own = Apply<RollingCdt>(g);
  CheckVec(relative.torque_i, {kMuR * kLoad * 1e-3, 0, 0});
  CheckVec(own.torque_i, relative.torque_i);
}
