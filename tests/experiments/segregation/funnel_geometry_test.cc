// The segregation funnel's orifice follows the fidelity so that it meters the same flow at
// every size scale. Beverloo's law, W = C ρ_b √g (D − k d)^{5/2} (Beverloo, Leniger & van de
// Velde 1961, Chem. Eng. Sci. 15:260), depends on the grains only through the open width
// D − k d (ρ_b does not change under a uniform size scale), so the rule's orifices at size ×5
// and ×4 (the quick and the default fidelity) must give one Beverloo flow, while one fixed
// orifice gives two; each must pass the jam rule D > 3 d_max at its own fidelity; and the rule
// must pass through the two orifices measured to meter the same flow (funnel_geometry.h).
#include "experiments/segregation/funnel_geometry.h"

#include <catch2/catch.hpp>

#include "core/bodies/clump_shapes.h"
#include "experiments/common/experiment_file.h"
#include "experiments/segregation/segregation_section.h"
#include "objectives/common/fidelity.h"
#include "objectives/metrics/beverloo.h"
#include "workflow/test_paths.h"

namespace demcal::objectives {
namespace {

constexpr double kC = 0.58;           // Beverloo's discharge coefficient (any value will do)
constexpr double kBulk = 476;         // kg/m³: 0.6 × the mixture's mean solid density
constexpr double kG = 9.81;           // m/s²

struct AtScale {
  double d_max_m = 0;
  double orifice_m = 0;
  SegregationSettings settings;
  core::Scene model;
};

AtScale ExampleAt(double size_scale) {
  workflow::ExperimentFile file;
  std::string error;
  const std::string path = (testing::RepoRoot() / "examples/segregation_paper.json").string();
  REQUIRE(workflow::LoadExperimentFile(path, &file, &error));
  Fidelity f = file.fidelity;
  f.size_scale = size_scale;
  AtScale out;
  out.model = file.model;
  ApplyFidelity(f, &out.model);
  INFO("size x" << size_scale);
  REQUIRE(workflow::ParseSegregationSection(file.section, path, out.model, &out.settings, &error));
  out.d_max_m = FeedMaxDiameter(out.model, out.settings.feed);
  out.orifice_m = out.settings.funnel.OrificeDiameterM(out.d_max_m);
  return out;
}

}  // namespace

TEST_CASE("funnel orifice rule: the same Beverloo flow at size x5 and x4, no jam", "[unit]") {
  const AtScale quick = ExampleAt(5), standard = ExampleAt(4);
  REQUIRE(quick.settings.funnel.ScalesWithFidelity());
  const double k = quick.settings.funnel.beverloo_k;
  // The TAED cut's 1000 µm upper edge sets d_max: 5 and 4 mm.
  CHECK(quick.d_max_m == Approx(0.005));
  CHECK(standard.d_max_m == Approx(0.004));
  // The orifice shrinks by k times the change of the largest grain.
  CHECK(quick.orifice_m - standard.orifice_m == Approx(k * 0.001));
  // The orifices measured to meter 10.3 g/s at both fidelities (funnel_geometry.h).
  CHECK(quick.orifice_m == Approx(0.0155));
  CHECK(standard.orifice_m == Approx(0.015));
  const double w_quick = BeverlooMassFlow(kC, k, quick.orifice_m, kBulk, quick.d_max_m, kG);
  const double w_standard =
      BeverlooMassFlow(kC, k, standard.orifice_m, kBulk, standard.d_max_m, kG);
  CHECK(w_quick > 0);
  CHECK(w_standard == Approx(w_quick).epsilon(1e-12));
  // Below the 20 g/s feed with the C 0.49–0.58 of Beverloo and of demcal's spheres: the funnel
  // backs up and the orifice sets the rate.
  CHECK(w_quick < 0.020);
  for (const AtScale* a : {&quick, &standard}) {
    CHECK(a->orifice_m > 3 * a->d_max_m);
    std::string error;
    CHECK(a->settings.IsValid(a->model, &error));
    INFO(error);
  }
  // The contrast the rule removes: the quick orifice kept fixed passes more at ×4.
  const double w_fixed = BeverlooMassFlow(kC, k, quick.orifice_m, kBulk, standard.d_max_m, kG);
  CHECK(w_fixed > w_quick);
}

TEST_CASE("funnel orifice rule: an open width that jams at its fidelity is refused", "[unit]") {
  // At size ×5 (d_max 5 mm) the rule needs an open width above (3 − k) × 5 mm = 12.5 mm.
  AtScale quick = ExampleAt(5);
  REQUIRE(quick.settings.funnel.beverloo_k == Approx(0.5));
  quick.settings.funnel.effective_orifice_diameter_m = 0.012;
  std::string error;
  CHECK_FALSE(quick.settings.IsValid(quick.model, &error));
  CHECK_THAT(error, Catch::Contains("segregation.funnel.effective_orifice_diameter_m") &&
                        Catch::Contains("would jam") && Catch::Contains("0.0125"));
}

TEST_CASE("funnel orifice rule: clumps by their mean caliper diameter, inside the measured band",
          "[unit]") {
  // The calibrated clumps of docs/experiments/segregation_funnel.md at size ×5 (BP 4 spheres on
  // a 3.36:1:1 spheroid, TAED 3 on 2.89, EP 3 on 2.83). Measured with them: 15.5 mm (the
  // sieve-equivalent rule) metered 6.9 g/s, 16.5 mm 10.4 g/s, 17.3 mm passed the whole 20 g/s.
  AtScale quick = ExampleAt(5);
  const std::vector<std::pair<double, int>> shapes = {{3.36, 4}, {2.89, 3}, {2.83, 3}};
  for (size_t k = 0; k < shapes.size(); ++k) {
    core::ShapeApproximation approx;
    std::string error;
    REQUIRE(core::ApproximateEllipsoid({shapes[k].first, 1, 1}, shapes[k].second, &approx,
                                       &error));
    for (const core::ClumpSphere& m : approx.spheres)
      quick.model.species[k].clump_shape.push_back({m.centre_m, m.radius_m});
  }
  const double sieve = FeedMaxDiameter(quick.model, quick.settings.feed);
  const double width = FeedMaxMeanCaliperDiameter(quick.model, quick.settings.feed);
  const double length = FeedMaxEnclosingDiameter(quick.model, quick.settings.feed);
  CHECK(sieve == Approx(0.005));
  CHECK(width > sieve);
  CHECK(length > width);
  const double orifice = quick.settings.funnel.OrificeDiameterM(width);
  CHECK(orifice > 0.0155);
  CHECK(orifice < 0.0173);
  std::string error;
  CHECK(quick.settings.IsValid(quick.model, &error));
  INFO(error);
}

TEST_CASE("funnel orifice: a fixed orifice ignores the grain size", "[unit]") {
  FunnelSettings f{.orifice_diameter_m = 0.014};
  CHECK_FALSE(f.ScalesWithFidelity());
  CHECK(f.OrificeDiameterM(0.001) == 0.014);
  CHECK(f.OrificeDiameterM(0.005) == 0.014);
  f.effective_orifice_diameter_m = 0.008;
  f.beverloo_k = 1.5;
  CHECK(f.OrificeDiameterM(0.002) == Approx(0.011));
}

}  // namespace demcal::objectives
