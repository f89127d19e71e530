// The feed's largest grain sizes (objectives/common/feed.h), which size the segregation funnel's
// feed region (enclosing diameter) and orifice (mean caliper diameter): a sphere's are its
// diameter; a clump's are checked against the closed forms for two touching equal spheres
// (radius r, centres ±r): union volume 2·(4/3)πr³, so the equivalent-volume diameter is
// 2r·2^{1/3}; the enclosing diameter 4r is 2^{2/3} of it and the mean caliper diameter 3r
// (core/bodies/clump_size.h) 1.5 / 2^{1/3}.
#include <catch2/catch.hpp>

#include <cmath>

#include "objectives/common/feed.h"

using namespace demcal;
using namespace demcal::objectives;

namespace {

core::Scene TwoSpecies() {
  core::Scene s;
  s.materials = {{"m", 1e7, 0.25, 2000}};
  s.species = {{"sphere", 0, {}, {}}, {"dimer", 0, {}, {}}};
  s.species[0].size.diameter_m = 0.004;
  s.species[1].size.diameter_m = 0.003;
  s.species[1].clump_shape = {{{-1, 0, 0}, 1}, {{1, 0, 0}, 1}};
  return s;
}

}  // namespace

TEST_CASE("a feed's largest grain sizes: a sphere's diameter, a dimer's by closed form", "[unit]") {
  const core::Scene s = TwoSpecies();
  Feed spheres;
  spheres.components = {{0, 1.0}};
  // Exactly the diameter, so a sphere feed's funnel and feed region are what they were.
  CHECK(FeedMaxEnclosingDiameter(s, spheres) == FeedMaxDiameter(s, spheres));
  CHECK(FeedMaxMeanCaliperDiameter(s, spheres) == FeedMaxDiameter(s, spheres));

  Feed dimers;
  dimers.components = {{1, 1.0}};
  CHECK(FeedMaxDiameter(s, dimers) == Approx(0.003));
  CHECK(FeedMaxEnclosingDiameter(s, dimers) == Approx(std::cbrt(4.0) * 0.003).epsilon(1e-9));
  CHECK(FeedMaxMeanCaliperDiameter(s, dimers) == Approx(1.5 / std::cbrt(2.0) * 0.003).epsilon(1e-3));

  // A mixture takes its largest grain: by length the 4.76 mm dimer, not the 4 mm sphere.
  Feed both;
  both.components = {{0, 0.5}, {1, 0.5}};
  CHECK(FeedMaxDiameter(s, both) == Approx(0.004));
  CHECK(FeedMaxEnclosingDiameter(s, both) == Approx(std::cbrt(4.0) * 0.003).epsilon(1e-9));
  // By mean width the 4 mm sphere is the larger: the dimer's is 3.57 mm.
  CHECK(FeedMaxMeanCaliperDiameter(s, both) == Approx(0.004).epsilon(1e-12));
}
