#include "calibrate/parameter_space.h"

#include <catch2/catch.hpp>

using namespace demcal;
using calibrate::PairProperty;
using calibrate::Parameter;
using calibrate::ParameterSpace;

namespace {

core::Scene TwoMaterials() {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}, {"perspex", 2.5e9, 0.25, 1180}};
  s.pair_parameters.assign(4, core::PairParameters{});
  return s;
}

}  // namespace

TEST_CASE("parameter space writes both orders of a pair", "[unit][calibrate]") {
  core::Scene model = TwoMaterials();
  ParameterSpace space;
  space.parameters.push_back({"mu_r", PairProperty::kRollingFriction, 0, 1, 0.0, 1.0, 0.1});
  space.parameters.push_back({"gamma", PairProperty::kInterfacialEnergy, 1, 1, 1e-3, 1.0, 0.05, true});
  std::string error;
  REQUIRE(space.IsValid(model, &error));
  space.Apply({0.35, 0.2}, &model);
  CHECK(model.pair_parameters[1].rolling_friction == 0.35);
  CHECK(model.pair_parameters[2].rolling_friction == 0.35);
  CHECK(model.pair_parameters[0].rolling_friction == 0.0);
  CHECK(model.pair_parameters[3].interfacial_energy_J_m2 == 0.2);
}

TEST_CASE("unit cube mapping: linear and logarithmic, round trip", "[unit][calibrate]") {
  ParameterSpace space;
  space.parameters.push_back({"a", PairProperty::kSlidingFriction, 0, 0, 0.2, 1.0, 0.5});
  space.parameters.push_back({"g", PairProperty::kInterfacialEnergy, 0, 0, 1e-3, 1e-1, 1e-2, true});
  const std::vector<double> u = space.ToUnit({0.6, 1e-2});
  CHECK(u[0] == Approx(0.5));
  CHECK(u[1] == Approx(0.5));  // 1e-2 is the geometric middle of [1e-3, 1e-1]
  const std::vector<double> back = space.FromUnit(u);
  CHECK(back[0] == Approx(0.6));
  CHECK(back[1] == Approx(1e-2));
  CHECK(space.FromUnit({-0.5, 2.0})[1] == Approx(1e-1));  // clamped into the bounds
}

TEST_CASE("parameter space errors name the field and the range", "[unit][calibrate]") {
  const core::Scene model = TwoMaterials();
  std::string error;
  ParameterSpace space;
  space.parameters.push_back({"mu", PairProperty::kSlidingFriction, 0, 0, 0.5, 0.2, 0.3});
  CHECK_FALSE(space.IsValid(model, &error));
  CHECK_THAT(error, Catch::StartsWith("parameters[0].min/max: need min < max within [0, ") &&
                        Catch::EndsWith("] (got [0.5, 0.2])"));  // 6 digits, as every range
  space.parameters[0] = {"mu", PairProperty::kSlidingFriction, 0, 2, 0.1, 0.9, 0.3};
  CHECK_FALSE(space.IsValid(model, &error));
  CHECK(error.find("parameters[0].materials") != std::string::npos);
  space.parameters[0] = {"mu", PairProperty::kSlidingFriction, 0, 1, 0.1, 0.9, 0.95};
  CHECK_FALSE(space.IsValid(model, &error));
  CHECK(error == "parameters[0].start: must lie in [min, max] = [0.1, 0.9]");
  space.parameters[0] = {"mu", PairProperty::kSlidingFriction, 0, 1, 0.1, 0.9, 0.5};
  space.parameters.push_back({"mu2", PairProperty::kSlidingFriction, 1, 0, 0.1, 0.9, 0.5});
  CHECK_FALSE(space.IsValid(model, &error));
  CHECK(error.find("parameters[1]") != std::string::npos);  // the same slot twice
  space.parameters.pop_back();
  space.parameters.push_back({"g", PairProperty::kInterfacialEnergy, 0, 0, 0.0, 0.5, 0.1, true});
  CHECK_FALSE(space.IsValid(model, &error));
  CHECK(error.find("parameters[1].log_scale") != std::string::npos);
}
