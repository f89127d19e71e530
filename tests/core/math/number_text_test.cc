// NumberText prints what a reader needs in a message: six significant digits in the shortest
// form, so a small value is not rounded away and a bound is not padded with zeros.
#include "core/math/number_text.h"

#include <catch2/catch.hpp>

using demcal::core::NumberText;

TEST_CASE("NumberText keeps small values and drops padding", "[unit][core]") {
  CHECK(NumberText(100) == "100");
  CHECK(NumberText(0.25) == "0.25");
  CHECK(NumberText(3.5e-5) == "3.5e-05");  // std::to_string gives "0.000035"
  CHECK(NumberText(1e-9) == "1e-09");      // std::to_string gives "0.000000"
  CHECK(NumberText(1e308) == "1e+308");
  CHECK(NumberText(2.0 / 3.0) == "0.666667");
}

TEST_CASE("NumberText rounds to a summary's own digit count", "[unit][core]") {
  CHECK(NumberText(2.0 / 3.0, 3) == "0.667");
  CHECK(NumberText(1234.5, 3) == "1.23e+03");  // the stream's shortest form, as summaries print
  CHECK(NumberText(0.5, 3) == "0.5");          // no padding at fewer digits either
  CHECK(NumberText(2.0 / 3.0, 6) == NumberText(2.0 / 3.0));
}
