// The clump aspect ratio as a calibrated property (calibrate/pair_property.h): it reshapes the
// clumped species of its material, keeping the sphere count, and leaves spheres and the pair
// table alone; bounds outside [1, 10] and a pair of two materials are refused by name.
#include <catch2/catch.hpp>

#include "calibrate/parameter_space.h"
#include "core/bodies/clump_shapes.h"

using namespace demcal;
using calibrate::PairProperty;
using calibrate::ParameterSpace;

namespace {

std::vector<core::ShapeSphere> Chain(double aspect, int n) {
  core::ShapeApproximation s;
  std::string error;
  REQUIRE(core::ApproximateEllipsoid({aspect, 1, 1}, n, &s, &error));
  std::vector<core::ShapeSphere> out;
  for (const core::ClumpSphere& c : s.spheres) out.push_back({c.centre_m, c.radius_m});
  return out;
}

core::Scene ClumpAndSphere() {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}, {"glass", 2.5e9, 0.25, 2500}};
  s.pair_parameters.assign(4, core::PairParameters{});
  s.species = {{.name = "BP", .material = 0, .clump_shape = Chain(2, 3)},
               {.name = "glass", .material = 1}};
  return s;
}

// Half the chain's length along its axis over its largest radius: the aspect ratio a/c it has.
double ChainAspect(const std::vector<core::ShapeSphere>& chain) {
  double half_length = 0, width = 0;
  for (const core::ShapeSphere& c : chain) {
    half_length = std::max(half_length, std::abs(c.centre.x) + c.radius);
    width = std::max(width, c.radius);
  }
  return half_length / width;
}

}  // namespace

TEST_CASE("aspect ratio: re-chains the clumped species of its material", "[unit][calibrate]") {
  core::Scene model = ClumpAndSphere();
  ParameterSpace space;
  space.parameters.push_back({"aspect_BP", PairProperty::kAspectRatio, 0, 0, 1.0, 3.5, 2.0});
  std::string error;
  REQUIRE(space.IsValid(model, &error));
  const core::PairParameters before = model.pair_parameters[0];
  space.Apply({3.0}, &model);
  // Three spheres still, now the tapered chain of [3, 1, 1]: the end spheres touch the tips at
  // ±3 and the widest sphere has radius 1 (clump_shapes.cc), so length/width is 3.
  REQUIRE(model.species[0].clump_shape.size() == 3);
  CHECK(ChainAspect(model.species[0].clump_shape) == Approx(3.0).epsilon(1e-9));
  CHECK(ChainAspect(Chain(2, 3)) == Approx(2.0).epsilon(1e-9));
  CHECK(model.species[1].clump_shape.empty());  // another material's sphere
  CHECK(model.pair_parameters[0].rolling_friction == before.rolling_friction);
  CHECK(model.pair_parameters[0].sliding_friction == before.sliding_friction);
  // A sphere of the material has no aspect ratio to set: left a sphere.
  model.species[0].clump_shape.clear();
  space.Apply({3.0}, &model);
  CHECK(model.species[0].clump_shape.empty());
}

TEST_CASE("aspect ratio: bounds and materials refused by name", "[unit][calibrate]") {
  const core::Scene model = ClumpAndSphere();
  std::string error;
  ParameterSpace below;
  below.parameters.push_back({"aspect_BP", PairProperty::kAspectRatio, 0, 0, 0.5, 3.5, 2.0});
  CHECK_FALSE(below.IsValid(model, &error));
  CHECK(error.find("parameters[0].min/max: need min < max within [1, 10]") != std::string::npos);
  ParameterSpace two;
  two.parameters.push_back({"aspect_BP", PairProperty::kAspectRatio, 0, 1, 1.0, 3.5, 2.0});
  CHECK_FALSE(two.IsValid(model, &error));
  CHECK(error.find("parameters[0].materials") != std::string::npos);
  // An experiment file's pair table holds pair properties only; a study may calibrate both.
  PairProperty p;
  CHECK_FALSE(calibrate::PairPropertyFromKey("aspect_ratio", &p));
  REQUIRE(calibrate::CalibratedPropertyFromKey("aspect_ratio", &p));
  CHECK(p == PairProperty::kAspectRatio);
  CHECK(calibrate::CalibratedPropertyFromKey("rolling_friction", &p));
}
