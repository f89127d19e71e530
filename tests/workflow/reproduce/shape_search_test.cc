// The per-count upper bound of the aspect-ratio search (shape_search.h): the longest chain whose
// spheres still touch.
#include "workflow/reproduce/shape_search.h"

#include <catch2/catch.hpp>

namespace demcal::workflow {
namespace {

TEST_CASE("aspect-ratio search: each count's bound is its longest connected chain", "[unit]") {
  // n equal spheres with the volume of the spheroid [a, 1, 1], n·(4/3)πr³ = (4/3)πa, end to
  // end over the length 2a touch when 2nr = 2a, i.e. n(a/n)³ = a: a = n. Tolerance: the chain
  // builder counts spheres within 1e-9 of its length as touching (clump_shapes.cc).
  CHECK(ConnectedAspectLimit(2, 1.0, 3.5) == Approx(2.0).epsilon(1e-8));
  CHECK(ConnectedAspectLimit(3, 1.0, 3.5) == Approx(3.0).epsilon(1e-8));
  // A sphere has no chain to part; bounds already inside the connected range stay.
  CHECK(ConnectedAspectLimit(1, 1.0, 3.5) == 3.5);
  CHECK(ConnectedAspectLimit(2, 1.0, 1.8) == 1.8);
  // Four and five stay connected over the bundled range (their tapered chains overlap).
  CHECK(ConnectedAspectLimit(4, 1.0, 3.5) == 3.5);
  CHECK(ConnectedAspectLimit(5, 1.0, 3.5) == 3.5);
}

}  // namespace
}  // namespace demcal::workflow
