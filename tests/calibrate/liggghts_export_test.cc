#include "calibrate/liggghts_export.h"

#include <catch2/catch.hpp>

using namespace demcal;

namespace {

core::Scene BpAndPerspex() {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}, {"perspex", 2.5e9, 0.3, 1180}};
  core::PairParameters bp{0.62, 0.34, 0.2, 0}, wall{0.42, 0.055, 0.28, 0};
  s.pair_parameters = {bp, wall, wall, {0.5, 0.01, 0.5, 0}};
  s.rolling.name = "cdt";
  return s;
}

}  // namespace

TEST_CASE("LIGGGHTS export: one type per material, full pair matrices, the rolling model", "[unit][calibrate]") {
  const std::string deck = calibrate::LiggghtsMaterialInclude(BpAndPerspex(), {"study: test"});
  CHECK_THAT(deck, Catch::Contains("# study: test"));
  CHECK_THAT(deck, Catch::Contains("# atom types: 1 = BP 2 = perspex"));
  CHECK_THAT(deck, Catch::Contains("pair_style gran model hertz tangential history rolling_friction cdt"));
  CHECK_THAT(deck, Catch::Contains("fix m1 all property/global youngsModulus peratomtype 2.5e+08 2.5e+09\n"));
  CHECK_THAT(deck, Catch::Contains("fix m2 all property/global poissonsRatio peratomtype 0.25 0.3\n"));
  CHECK_THAT(deck, Catch::Contains("coefficientRestitution peratomtypepair 2 0.2 0.28 0.28 0.5\n"));
  CHECK_THAT(deck, Catch::Contains("coefficientFriction peratomtypepair 2 0.62 0.42 0.42 0.5\n"));
  CHECK_THAT(deck, Catch::Contains("coefficientRollingFriction peratomtypepair 2 0.34 0.055 0.055 0.01\n"));
  CHECK_THAT(deck, !Catch::Contains("Gamma"));  // no adhesion in this model
}

TEST_CASE("LIGGGHTS export: no rolling keyword for 'none', epsd damping, Gamma as a comment", "[unit][calibrate]") {
  core::Scene m = BpAndPerspex();
  m.rolling.name = "none";
  m.pair_parameters[0].interfacial_energy_J_m2 = 0.046;
  std::string deck = calibrate::LiggghtsMaterialInclude(m, {});
  CHECK_THAT(deck, Catch::Contains("model hertz tangential history\n"));
  CHECK_THAT(deck, !Catch::Contains("coefficientRollingFriction"));
  CHECK_THAT(deck, Catch::Contains("(no JKR model): 0.046 0 0 0"));
  m.rolling = {"epsd", 0.3};
  deck = calibrate::LiggghtsMaterialInclude(m, {});
  CHECK_THAT(deck, Catch::Contains("coefficientRollingViscousDamping peratomtypepair 2 0.3 0.3 0.3 0.3\n"));
}
