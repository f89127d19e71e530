#include "calibrate/liggghts_export.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

using namespace demcal;

namespace {

// BP grains (d 0.5 mm) in a Perspex box: BP–BP meets grain–grain contacts, BP–Perspex
// grain–wall ones, Perspex–Perspex none.
core::Scene BpAndPerspex() {
  core::Scene s;
  s.materials = {{"BP", 2.5e8, 0.25, 780}, {"perspex", 2.5e9, 0.3, 1180}};
  core::PairParameters bp{0.62, 0.34, 0.2, 0}, wall{0.42, 0.055, 0.28, 0};
  s.pair_parameters = {bp, wall, wall, {0.5, 0.01, 0.5, 0}};
  s.rolling.name = "cdt";
  core::Species grains;
  grains.name = "BP";
  grains.material = 0;
  grains.size.diameter_m = 5e-4;
  s.species = {grains};
  return s;
}

calibrate::LiggghtsLawOptions Torque() {
  calibrate::LiggghtsLawOptions o;
  o.cdt_torque_conversion = true;
  return o;
}

}  // namespace

TEST_CASE("LIGGGHTS export: epsd2 maps unchanged, one type per material, full matrices",
          "[unit][calibrate]") {
  core::Scene m = BpAndPerspex();
  m.rolling.name = "epsd2";
  const std::string deck = calibrate::LiggghtsMaterialInclude(m, {"study: test"});
  CHECK_THAT(deck, Catch::Contains("# study: test"));
  CHECK_THAT(deck, Catch::Contains("# atom types: 1 = BP 2 = perspex"));
  CHECK_THAT(deck, Catch::Contains(
                       "pair_style gran model hertz tangential history rolling_friction epsd2"));
  CHECK_THAT(deck, Catch::Contains(
                       "fix m1 all property/global youngsModulus peratomtype 2.5e+08 2.5e+09\n"));
  CHECK_THAT(deck,
             Catch::Contains("fix m2 all property/global poissonsRatio peratomtype 0.25 0.3\n"));
  CHECK_THAT(deck, Catch::Contains("coefficientRestitution peratomtypepair 2 0.2 0.28 0.28 0.5\n"));
  CHECK_THAT(deck, Catch::Contains("coefficientFriction peratomtypepair 2 0.62 0.42 0.42 0.5\n"));
  CHECK_THAT(deck, Catch::Contains(
                       "coefficientRollingFriction peratomtypepair 2 0.34 0.055 0.055 0.01\n"));
}

TEST_CASE("LIGGGHTS export: cdt is refused by default, naming the pair and the law",
          "[unit][calibrate]") {
  const core::Scene m = BpAndPerspex();
  calibrate::LiggghtsLaw law;
  std::string error;
  CHECK_FALSE(calibrate::ConvertToLiggghts(m, calibrate::ContactUseOf(m, {1}), {}, &law, &error));
  CHECK_THAT(error, Catch::Contains("material pair BP–BP") && Catch::Contains("cdt") &&
                        Catch::Contains("--rolling-conversion torque"));
  // The bare include says so instead of writing a coefficient that would be misread.
  const std::string deck = calibrate::LiggghtsMaterialInclude(m, {});
  CHECK_THAT(deck, Catch::Contains("# NOT EXPORTED: material pair BP–BP"));
  CHECK_THAT(deck, !Catch::Contains("coefficientRollingFriction"));
}

TEST_CASE("LIGGGHTS export: the cdt torque conversion, grain–grain and grain–wall",
          "[unit][calibrate]") {
  // LIGGGHTS applies μr·Fn·R* with R* = R_i R_j/(R_i + R_j) (R_i on a wall); demcal μr·Fn·R_i:
  // equal spheres need 2×, a wall 1×; radii 1 and 3: (1+3)²/(2·3) = 8/3.
  CHECK(calibrate::CdtParticleFactor(1e-3, 1e-3) == Approx(2.0));
  CHECK(calibrate::CdtParticleFactor(1e-3, 3e-3) == Approx(8.0 / 3.0));
  const core::Scene m = BpAndPerspex();
  calibrate::LiggghtsLaw law;
  std::string error;
  REQUIRE(calibrate::ConvertToLiggghts(m, calibrate::ContactUseOf(m, {1}), Torque(), &law, &error));
  REQUIRE(law.rolling_coefficient.size() == 4);
  CHECK(law.rolling_coefficient[0] == Approx(0.68));   // BP–BP ×2
  CHECK(law.rolling_coefficient[1] == Approx(0.055));  // BP–Perspex ×1
  CHECK(law.rolling_coefficient[3] == Approx(0.01));   // unused pair left alone
  REQUIRE(law.notes.size() == 1);
  CHECK_THAT(law.notes[0], Catch::Contains("BP–BP") && Catch::Contains("×2"));
  // A box of BP: BP–BP would need ×2 and ×1 in one coefficient.
  CHECK_FALSE(
      calibrate::ConvertToLiggghts(m, calibrate::ContactUseOf(m, {0}), Torque(), &law, &error));
  CHECK_THAT(error, Catch::Contains("BP–BP") && Catch::Contains("grain–wall"));
}

TEST_CASE("LIGGGHTS export: JKR is refused naming the pair, or written as sjkr on request",
          "[unit][calibrate]") {
  core::Scene m = BpAndPerspex();
  m.rolling.name = "epsd2";
  m.pair_parameters[1].interfacial_energy_J_m2 = m.pair_parameters[2].interfacial_energy_J_m2 =
      0.05;
  calibrate::LiggghtsLaw law;
  std::string error;
  const calibrate::ContactUse use = calibrate::ContactUseOf(m, {1});
  CHECK_FALSE(calibrate::ConvertToLiggghts(m, use, {}, &law, &error));
  CHECK_THAT(error, Catch::Contains("material pair BP–perspex") && Catch::Contains("JKR"));
  calibrate::LiggghtsLawOptions sjkr;
  sjkr.sjkr_approximation = true;
  REQUIRE(calibrate::ConvertToLiggghts(m, use, sjkr, &law, &error));
  CHECK_THAT(law.model, Catch::EndsWith("cohesion sjkr rolling_friction epsd2"));
  REQUIRE(law.cohesion_energy_density_J_m3.size() == 4);
  CHECK(law.cohesion_energy_density_J_m3[0] == 0);
  CHECK(law.cohesion_energy_density_J_m3[1] > 0);
  CHECK_THAT(
      calibrate::LiggghtsMaterialLines(m, law),
      Catch::Contains("fix m7 all property/global cohesionEnergyDensity peratomtypepair 2 0 "));
}

TEST_CASE("LIGGGHTS export: a pair with sjkr's own k is written as cohesion sjkr, unchanged",
          "[unit][calibrate]") {
  core::Scene m = BpAndPerspex();
  m.rolling.name = "epsd2";
  m.pair_parameters[0].cohesion_energy_density_J_m3 = 7500;
  calibrate::LiggghtsLaw law;
  std::string error;
  // No approximation asked for: it is LIGGGHTS' own law (core/contact/sjkr.h).
  REQUIRE(calibrate::ConvertToLiggghts(m, calibrate::ContactUseOf(m, {1}), {}, &law, &error));
  CHECK_THAT(law.model, Catch::EndsWith("cohesion sjkr rolling_friction epsd2"));
  CHECK(law.cohesion_energy_density_J_m3 == std::vector<double>{7500, 0, 0, 0});
  CHECK(law.notes.empty());
  CHECK_THAT(calibrate::LiggghtsMaterialLines(m, law),
             Catch::Contains("fix m7 all property/global cohesionEnergyDensity peratomtypepair 2 "
                             "7500 0 "));
}

TEST_CASE("LIGGGHTS export: sjkr's k carries JKR's pull-off force at its zero-load contact",
          "[unit][calibrate]") {
  // JKR (work of adhesion w = 2Γ): pull-off 3πΓR*, zero-load contact radius a0³ = 9πΓR*²/E*
  // (Johnson, Kendall & Roberts 1971). sjkr's force k·πa² at a = a0 must equal the pull-off.
  const double gamma = 0.046, e = 2.5e6, r = 2.5e-4;
  const double k = calibrate::SjkrEnergyDensity(gamma, e, r);
  const double a0 = std::cbrt(9 * std::numbers::pi * gamma * r * r / e);
  CHECK(k * std::numbers::pi * a0 * a0 == Approx(3 * std::numbers::pi * gamma * r).epsilon(1e-12));
  // k ∝ Γ^{1/3} E*^{2/3} R*^{-1/3}.
  CHECK(calibrate::SjkrEnergyDensity(8 * gamma, e, r) == Approx(2 * k));
  CHECK(calibrate::SjkrEnergyDensity(gamma, 8 * e, r) == Approx(4 * k));
}

TEST_CASE("LIGGGHTS export: no rolling keyword for 'none', epsd damping", "[unit][calibrate]") {
  core::Scene m = BpAndPerspex();
  m.rolling.name = "none";
  std::string deck = calibrate::LiggghtsMaterialInclude(m, {});
  CHECK_THAT(deck, Catch::Contains("model hertz tangential history\n"));
  CHECK_THAT(deck, !Catch::Contains("coefficientRollingFriction"));
  m.rolling = {"epsd", 0.3};
  deck = calibrate::LiggghtsMaterialInclude(m, {});
  CHECK_THAT(deck, Catch::Contains(
                       "coefficientRollingViscousDamping peratomtypepair 2 0.3 0.3 0.3 0.3\n"));
}

TEST_CASE("LIGGGHTS export: cdt_relative is LIGGGHTS' cdt, exported unchanged without a flag",
          "[unit][calibrate]") {
  // Same lever R* and same relative rotation in both codes (docs/physics.md §2.1), so no
  // conversion and no refusal: the coefficients go across as they are.
  core::Scene m = BpAndPerspex();
  m.rolling.name = "cdt_relative";
  calibrate::LiggghtsLaw law;
  std::string error;
  REQUIRE(calibrate::ConvertToLiggghts(m, calibrate::ContactUseOf(m, {1}), {}, &law, &error));
  CHECK(law.model == "model hertz tangential history rolling_friction cdt");
  CHECK(law.notes.empty());
  const std::string deck = calibrate::LiggghtsMaterialInclude(m, {});
  CHECK_THAT(deck, Catch::Contains(
                       "coefficientRollingFriction peratomtypepair 2 0.34 0.055 0.055 0.01\n"));
  CHECK_THAT(deck, !Catch::Contains("NOT EXPORTED"));
}
