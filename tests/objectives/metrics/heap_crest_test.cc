// Crest drop (heap_crest.h) on constructed slot heaps of known shape (sloped_heaps.h): a sharp
// triangle has its top on the flank lines; a crest flattened by c lies c below their apex.
#include "objectives/metrics/heap_crest.h"

#include <catch2/catch.hpp>

#include "objectives/metrics/sloped_heaps.h"

using namespace demcal::objectives;
using namespace demcal::objectives::testing;

TEST_CASE("crest drop: a sharp heap is a cone, a flattened crest drops by its cut", "[unit]") {
  const double d = 2e-3;
  SlotHeapShape shape;
  shape.height_m = 0.04;
  shape.left_deg = shape.right_deg = 35;
  const ReposeAngle sharp = MeasureSlotHeapAngle(SlotHeap(shape, d, {}), {});
  REQUIRE(sharp.ok);
  // The profile samples tops every half diameter: the apex is found to within that.
  CHECK(std::abs(CrestDrop(sharp, 0)) < d / 2);

  shape.top_cut_m = 0.006;  // three diameters: well inside the 90% window limit of H' = 34 mm
  const ReposeAngle rounded = MeasureSlotHeapAngle(SlotHeap(shape, d, {}), {});
  REQUIRE(rounded.ok);
  CHECK(rounded.angle_deg == Approx(35).margin(0.5));  // the slope is unchanged
  CHECK(CrestDrop(rounded, 0) == Approx(shape.top_cut_m).margin(d / 2));
}

TEST_CASE("crest drop is 0 for a heap that was not measured", "[unit]") {
  CHECK(CrestDrop(ReposeAngle{}, 0) == 0);
}
