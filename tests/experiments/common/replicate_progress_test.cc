// ReplicateProgress (experiments/common/replicate_progress.h): the percentage a replicate shows
// never falls back when its expected end moves later.
#include "experiments/common/replicate_progress.h"

#include <catch2/catch.hpp>
#include <sstream>

namespace demcal::workflow {

TEST_CASE("replicate progress holds its percentage when the expected end moves later",
          "[unit]") {
  std::ostringstream out;
  ReplicateProgress progress(out, "segregation", 1, true, 0.0);
  progress.Update(0, 1.0, 2.0);  // half way, by the estimate of the moment
  progress.Update(0, 1.1, 6.0);  // the end moved to the hard stop: 18 % by itself
  progress.Update(0, 5.4, 6.0);  // 90 %
  const std::string text = out.str();
  CHECK(text.find("50.0%") != std::string::npos);
  CHECK(text.find("18.3%") == std::string::npos);
  CHECK(text.find("90.0%") != std::string::npos);
  // The second line still says 50 %: two lines at 50.0 %, then 90.0 %.
  CHECK(text.find("50.0%", text.find("50.0%") + 1) != std::string::npos);
}

}  // namespace demcal::workflow
