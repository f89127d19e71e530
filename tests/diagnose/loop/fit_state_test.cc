// The fixed floor is the packing noise of the measured value: one single-run scatter for a value
// measured on one packing, 1/√n of it for the mean of n (the variance of a mean of n draws).
#include "diagnose/loop/fit_state.h"

#include <catch2/catch.hpp>

namespace demcal::diagnose {

TEST_CASE("the fixed floor of a mean over n repeats is the scatter over sqrt(n)", "[unit]") {
  std::vector<Observation> obs(3);
  obs[0].repeats = 0;  // not stated: one packing
  obs[1].repeats = 1;
  obs[2].repeats = 4;
  Prediction p{true, "ok", {10, 10, 10}, {0.5, 0.5, 0.5}, {2.0, 2.0, 2.0}};
  const std::vector<Observation> at = WithPrediction(obs, p, 1.0);
  CHECK(at[0].floor == Approx(2.0));
  CHECK(at[1].floor == Approx(2.0));
  CHECK(at[2].floor == Approx(1.0));
  CHECK(at[2].scatter == Approx(2.0));  // the estimated floor's unit stays one packing
  CHECK(WithPrediction(obs, p, 0.0)[2].floor == 0.0);
}

}  // namespace demcal::diagnose
