#include "objectives/common/input_limits.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "calibrate/optimiser.h"
#include "objectives/common/fidelity.h"

namespace limits = demcal::objectives::limits;

TEST_CASE("input limits print as the messages quote them and refuse NaN", "[unit]") {
  CHECK(limits::kSizeScale.Text() == "[1, 20]");
  CHECK(limits::kStiffnessScale.Text() == "(0, 1]");
  CHECK(limits::kUnitTolerance.Text() == "(0, 0.5)");
  CHECK(limits::kMaxEvaluations.Text() == "[1, 100000]");
  CHECK(limits::kClumpSpheres.Text() == "[1, 5]");
  CHECK(limits::kStiffnessScale.Contains(1));
  CHECK_FALSE(limits::kStiffnessScale.Contains(0));
  CHECK_FALSE(limits::kUnitTolerance.Contains(0.5));
  CHECK_FALSE(limits::kSizeScale.Contains(std::nan("")));
}

// Each IsValid quotes the table: a limit changed there changes the rule and its message.
TEST_CASE("IsValid of fidelity and optimiser options apply the table's limits", "[unit]") {
  std::string error;
  demcal::objectives::Fidelity f;
  f.size_scale = limits::kSizeScale.hi;
  CHECK(f.IsValid(&error));
  f.size_scale = limits::kSizeScale.hi * 1.01;
  CHECK_FALSE(f.IsValid(&error));
  CHECK(error == "fidelity.size_scale = 20.2 is outside the allowed range [1, 20]");
  demcal::calibrate::OptimiserOptions o;
  o.max_evaluations = static_cast<int>(limits::kMaxEvaluations.hi);
  CHECK(o.IsValid(&error));
  o.max_evaluations += 1;
  CHECK_FALSE(o.IsValid(&error));
  CHECK(error == "max_evaluations: must be in [1, 100000]");
}
