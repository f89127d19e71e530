// The rolling lever of `cdt` on clump members: EDEM's Standard Rolling Friction takes R_i as "the
// distance of the contact point from the center of mass" (Altair EDEM help, "Standard Rolling
// Friction Model"; docs/physics.md §2.1). Hand-made geometry against that distance, computed
// here from the positions; free spheres keep their radius.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/contact/clump_levers.h"
#include "core/contact/contact_kernel.h"
#include "core/contact/hertz_mindlin.h"
#include "core/contact/rolling_model.h"

using namespace demcal::core;

namespace {

constexpr double kR = 1e-3, kOverlap = 2e-6;

// Slot 0: a member of clump 0 whose centre is at the origin, the member 1.5 mm along x.
// Slot 1: a free sphere.
Particles TwoSlots(const Vec3& free_sphere_at) {
  Particles p;
  p.Add(1, 0, 0, kR, 1000, {1.5e-3, 0, 0}, {}, {});
  p.Add(2, 0, 0, kR, 1000, free_sphere_at, {}, {});
  p.body[0] = 0;
  return p;
}

ContactGeometry Touching(const Vec3& normal) {
  ContactGeometry g{};
  g.normal = normal;
  g.overlap_m = kOverlap;
  g.radius_i_m = g.rolling_lever_i_m = kR;
  g.radius_j_m = g.rolling_lever_j_m = kR;
  return g;
}

}  // namespace

TEST_CASE("clump levers: a member's lever is the distance from its clump's centre to the contact point",
          "[unit][contact][clump]") {
  const std::vector<Vec3> centres = {{0, 0, 0}};
  // The free sphere sits on top of the member (+z); the contact point is at depth r − δ/2 below
  // the free sphere's centre, above the member's centre.
  const Vec3 above{1.5e-3, 0, 2 * kR - kOverlap};
  Particles p = TwoSlots(above);
  const Vec3 contact{1.5e-3, 0, kR - kOverlap / 2};
  SECTION("the member as i (normal from the free sphere towards it)") {
    // Free sphere j = 1 above i = 0: the normal from j to i points down.
    ContactGeometry g = Touching({0, 0, -1});
    SetClumpLevers(p, centres, 0, 1, g);
    CHECK(g.rolling_lever_i_m == Approx(Norm(contact - centres[0])).epsilon(1e-12));
    CHECK(g.rolling_lever_j_m == kR);  // a free sphere keeps its radius
  }
  SECTION("the member as j") {
    ContactGeometry g = Touching({0, 0, 1});  // from j = 0 (member) up to i = 1
    SetClumpLevers(p, centres, 1, 0, g);
    CHECK(g.rolling_lever_i_m == kR);
    CHECK(g.rolling_lever_j_m == Approx(Norm(contact - centres[0])).epsilon(1e-12));
  }
  SECTION("on a wall: a chain lying on a floor rolls about its axis with the lever √(d² + (r − δ/2)²)") {
    ContactGeometry g = Touching({0, 0, 1});
    g.radius_j_m = g.rolling_lever_j_m = 0;
    SetClumpLevers(p, centres, 0, -1, g);
    const double d = 1.5e-3, depth = kR - kOverlap / 2;
    CHECK(g.rolling_lever_i_m == Approx(std::sqrt(d * d + depth * depth)).epsilon(1e-12));
    CHECK(g.rolling_lever_i_m > 1.8 * kR);  // the end of a chain brakes its spin ~2× harder
  }
  SECTION("the cdt torque uses the lever: μr Fn R_i against the body's spin") {
    ContactGeometry g = Touching({0, 0, 1});
    g.omega_i = {0, 3, 0};
    SetClumpLevers(p, centres, 0, -1, g);
    ResolvedPair pair;
    pair.rolling_friction = 0.1;
    NormalForce n;
    n.rolling_load_N = 2.0;
    ContactHistory h;
    ContactResult r;
    RollingCdt{}.Apply(g, pair, n, 1e-6, h, r);
    CHECK(r.torque_i.y == Approx(-0.1 * 2.0 * g.rolling_lever_i_m).epsilon(1e-12));
  }
}

TEST_CASE("clump levers: free spheres keep their radius exactly", "[unit][contact][clump]") {
  Particles p = TwoSlots({1.5e-3, 0, 2 * kR - kOverlap});
  p.body[0] = -1;
  ContactGeometry g = Touching({0, 0, -1});
  SetClumpLevers(p, std::vector<Vec3>{{0, 0, 0}}, 0, 1, g);
  CHECK(g.rolling_lever_i_m == kR);
  CHECK(g.rolling_lever_j_m == kR);
}

TEST_CASE("clump levers: computed only for a rolling law that reads them", "[unit][contact][clump]") {
  // cdt's torque uses the levers; the others use the radii (cdt_relative's R*, epsd's R_eff), so
  // their clump scenes skip SetClumpLevers at compile time.
  STATIC_REQUIRE(ContactModel<HertzMindlinNormal, RollingCdt>::kReadsRollingLever);
  STATIC_REQUIRE_FALSE(ContactModel<HertzMindlinNormal, RollingCdtRelative>::kReadsRollingLever);
  STATIC_REQUIRE_FALSE(ContactModel<HertzMindlinNormal, RollingEpsd>::kReadsRollingLever);
  STATIC_REQUIRE_FALSE(ContactModel<HertzMindlinNormal, RollingNone>::kReadsRollingLever);
}
