#include "outputs/progress_reporter.h"

#include <catch2/catch.hpp>
#include <sstream>

using namespace demcal::workflow;

TEST_CASE("the ETA extrapolates the simulated-time rate so far", "[unit]") {
  ProgressSample s;
  s.simulated_time_s = 0.25;
  s.duration_s = 1.0;
  s.elapsed_wall_s = 10;
  CHECK(EstimateRemainingWallTime(s) == Approx(30));
  s.simulated_time_s = 0;
  CHECK(EstimateRemainingWallTime(s) < 0);  // unknown before any progress
}

TEST_CASE("a progress line shows percent, simulated time, particles, elapsed time and ETA",
          "[unit]") {
  ProgressSample s;
  s.simulated_time_s = 0.21;
  s.duration_s = 0.5;
  s.particles = 3000;
  s.elapsed_wall_s = 8.4;
  const std::string line = FormatProgressLine(s);
  CHECK_THAT(line, Catch::Contains("42.0%"));
  CHECK_THAT(line, Catch::Contains("t = 0.21 / 0.5 s"));
  CHECK_THAT(line, Catch::Contains("3000 particles"));
  CHECK_THAT(line, Catch::Contains("elapsed 8.4 s"));
  CHECK_THAT(line, Catch::Contains("ETA 11.6 s"));
}

TEST_CASE("durations are written in s, min or h as fits", "[unit]") {
  CHECK(FormatDuration(8.44) == "8.4 s");
  CHECK(FormatDuration(192) == "3 min 12 s");
  CHECK(FormatDuration(3900) == "1 h 05 min");
  CHECK(FormatDuration(-1) == "?");
}

TEST_CASE("the reporter stays silent within its interval and when disabled", "[unit]") {
  std::ostringstream out;
  ProgressReporter slow(out, 1.0, {.interval_s = 3600, .enabled = true});
  slow.Update(0.5, 10);
  CHECK(out.str().empty());
  ProgressReporter quiet(out, 1.0, {.interval_s = 1e-12, .enabled = false});
  quiet.Update(0.5, 10);
  CHECK(out.str().empty());
  ProgressReporter eager(out, 1.0, {.interval_s = 1e-12, .enabled = true});
  eager.Update(0.5, 10);
  CHECK(eager.lines_printed() == 1);
  CHECK_THAT(out.str(), Catch::StartsWith("[demcal]  50.0%"));
}
