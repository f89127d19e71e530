#include "experiments/discharge/sphere_mass_share.h"

#include <catch2/catch.hpp>

namespace demcal::objectives {

TEST_CASE("sphere mass shares count a clump once, not once per member", "[unit]") {
  core::Particles p;
  for (int i = 0; i < 4; ++i) p.Add(i, 0, 0, 1e-3, 1000.0, {}, {}, {});
  p.mass_kg[0] = 2.0;
  // Spheres 1-3 are the members of clump 0: each carries the clump's 6 kg (core/bodies/clumps.cc).
  for (int i = 1; i < 4; ++i) p.body[i] = 0, p.mass_kg[i] = 6.0;
  const std::vector<double> share = SphereMassShares(p);
  REQUIRE(share.size() == 4);
  CHECK(share[0] == 2.0);
  CHECK(share[1] + share[2] + share[3] == Approx(6.0));
}

}  // namespace demcal::objectives
