// The mean caliper diameter (core/bodies/clump_size.h) against closed forms: a sphere's width is
// its diameter in every direction; two touching spheres of radius r with centres ±r·x have the
// width 2r + 2r|u_x|, and |u_x| averages 1/2 over the unit sphere (Archimedes' hat-box theorem:
// u_x is uniform on [−1, 1]), so the mean is 3r; a long chain approaches Cauchy's r + L/2.
#include "core/bodies/clump_size.h"

#include <catch2/catch.hpp>

using namespace demcal::core;

TEST_CASE("mean caliper diameter: a sphere's diameter, a dimer's 3r, a chain's r + L/2",
          "[unit]") {
  CHECK(MeanCaliperDiameter({}) == 0);
  CHECK(MeanCaliperDiameter({{{0.3, -0.2, 0.1}, 0.5}}) == Approx(1.0).epsilon(1e-12));

  const double r = 0.7;
  const double dimer = MeanCaliperDiameter({{{-r, 0, 0}, r}, {{r, 0, 0}, r}});
  CHECK(dimer == Approx(3 * r).epsilon(1e-3));
  // The direction of the axis does not matter beyond the lattice's error.
  const double s = r / std::sqrt(3.0);
  CHECK(MeanCaliperDiameter({{{-s, -s, -s}, r}, {{s, s, s}, r}}) == Approx(dimer).epsilon(1e-3));

  // 11 overlapping spheres on a segment of length 2h: the hull is nearly a spherocylinder,
  // whose mean width is 2r + h (Cauchy: a segment's mean width is half its length).
  std::vector<ClumpSphere> chain;
  const double h = 5;
  for (int k = 0; k <= 10; ++k) chain.push_back({{-h + k * h / 5, 0, 0}, 1.0});
  CHECK(MeanCaliperDiameter(chain) == Approx(2 * 1.0 + h).epsilon(2e-3));
}
