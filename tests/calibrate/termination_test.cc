#include "calibrate/termination.h"

#include <catch2/catch.hpp>
#include <string>

using demcal::calibrate::ParseTermination;
using demcal::calibrate::Termination;
using demcal::calibrate::TerminationName;

// The names are what result.json, evaluations and clump-count tables carry; a renamed one would
// make older outputs unreadable by reproduce.
TEST_CASE("calibration terminations keep their file names and read back", "[unit][calibrate]") {
  const std::pair<Termination, std::string> names[] = {
      {Termination::kWithinNoise, "within_noise"}, {Termination::kConverged, "converged"},
      {Termination::kOutOfRange, "out_of_range"},  {Termination::kBudget, "budget"},
      {Termination::kFailed, "failed"},            {Termination::kInvalid, "invalid"}};
  for (const auto& [t, name] : names) {
    CHECK(TerminationName(t) == name);
    Termination back = Termination::kInvalid == t ? Termination::kFailed : Termination::kInvalid;
    REQUIRE(ParseTermination(name, &back));
    CHECK(back == t);
  }
  Termination untouched = Termination::kBudget;
  CHECK_FALSE(ParseTermination("Within_noise", &untouched));
  CHECK_FALSE(ParseTermination("", &untouched));
  CHECK(untouched == Termination::kBudget);
}
