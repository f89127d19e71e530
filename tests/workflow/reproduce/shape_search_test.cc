// The per-count range of the aspect-ratio search (aspect_bounds.h, shape_search.h): from the
// shortest chain whose spheres stand apart to the longest whose spheres still touch; the search's
// bracket and the workflow file's check use both.
#include "workflow/reproduce/shape_search.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "workflow/reproduce/species_twin.h"

namespace demcal::workflow {
namespace {

TEST_CASE("aspect-ratio search: each count's bound is its longest connected chain",
          "[unit][shape]") {
  // n equal spheres with the volume of the spheroid [a, 1, 1], n·(4/3)πr³ = (4/3)πa, end to
  // end over the length 2a touch when 2nr = 2a, i.e. n(a/n)³ = a: a = n. Tolerance: the chain
  // builder counts spheres within 1e-9 of its length as touching (clump_shapes.cc).
  CHECK(ConnectedAspectLimit(2, 1.0, 3.5) == Approx(2.0).epsilon(1e-8));
  CHECK(ConnectedAspectLimit(3, 1.0, 3.5) == Approx(3.0).epsilon(1e-8));
  // A sphere has no chain to part; bounds already inside the connected range stay.
  CHECK(ConnectedAspectLimit(1, 1.0, 3.5) == 3.5);
  CHECK(ConnectedAspectLimit(2, 1.0, 1.8) == 1.8);
  // Four and five stay connected over the bundled range (their tapered chains overlap).
  CHECK(ConnectedAspectLimit(4, 1.0, 3.5) == 3.5);
  CHECK(ConnectedAspectLimit(5, 1.0, 3.5) == 3.5);
}

TEST_CASE("aspect-ratio search: each count's lower bound is its shortest distinct chain",
          "[unit][shape]") {
  // At a = 1 every chain is n spheres on one another (clump_shapes.cc: a sphere target puts
  // them all at the origin): nothing a heap can be made of at the engine's time step.
  for (int n = 2; n <= 5; ++n) CHECK(MinMemberSpacing(n, 1.0) < 0.01);
  CHECK(std::isinf(MinMemberSpacing(1, 1.0)));
  // Two equal spheres of radius r, centres s = 0.15 r apart, end to end over 2a = 2r + s, with
  // the spheroid's volume (4/3)πa: two balls less their lens, (4/3)π·2r³ − π(4r + s)(2r − s)²/12
  // (the lens of two equal spheres). With s = 0.15 r and a = 1.075 r this gives r² and a:
  const double s = kMinMemberSpacing;
  const double union_over_r3 =
      (4.0 / 3.0) * std::numbers::pi * 2 - std::numbers::pi * (4 + s) * (2 - s) * (2 - s) / 12;
  const double r = std::sqrt((4.0 / 3.0) * std::numbers::pi * (1 + s / 2) / union_over_r3);
  const double a2 = (1 + s / 2) * r;  // ≈ 1.0568
  CHECK(DistinctAspectLimit(2, 1.0, 3.5) == Approx(a2).epsilon(1e-8));
  // Every count's bound is where its spacing reaches the rule, and each longer count packs more
  // spheres into the length, so it needs a longer chain.
  double previous = 1.0;
  for (int n = 2; n <= 5; ++n) {
    INFO(n << " spheres");
    const double lo = DistinctAspectLimit(n, 1.0, 3.5);
    CHECK(MinMemberSpacing(n, lo) == Approx(kMinMemberSpacing).epsilon(1e-6));
    CHECK(MinMemberSpacing(n, 0.99 * lo + 0.01) < kMinMemberSpacing);
    CHECK(lo > previous);
    CHECK(lo < ConnectedAspectLimit(n, 1.0, 3.5));
    previous = lo;
  }
  // A sphere has no chain; a range already past the bound keeps its own minimum.
  CHECK(DistinctAspectLimit(1, 1.0, 3.5) == 1.0);
  CHECK(DistinctAspectLimit(2, 1.5, 3.5) == 1.5);
}

TEST_CASE("aspect-ratio search: a count's bracket is the workflow range cut to its grains",
          "[unit][shape]") {
  WorkflowFile w = testing_twin::TwinWorkflow("unused.csv", {1, 2, 3});
  w.species[0].semi_axes.clear();
  w.species[0].aspect_ratio = {
      .min = 1.0, .max = 3.5, .start = 2.5, .max_evaluations = 6, .enabled = true};
  const CalibrationStep two = ShapeStep(w, 0, 2, "experiment.json", "clumps_2");
  CHECK(two.property == "aspect_ratio");
  CHECK(two.min == Approx(DistinctAspectLimit(2, 1.0, 3.5)).epsilon(1e-10));
  CHECK(two.max == ConnectedAspectLimit(2, 1.0, 3.5));
  CHECK(two.start == two.max);  // the workflow's start 2.5 lies past the connected chains
  const CalibrationStep three = ShapeStep(w, 0, 3, "experiment.json", "clumps_3");
  CHECK(three.min == Approx(DistinctAspectLimit(3, 1.0, 3.5)).epsilon(1e-10));
  CHECK(three.start == 2.5);
  // Count 1 is one candidate, the sphere at the held property: no aspect ratio to bound.
  const CalibrationStep one = ShapeStep(w, 0, 1, "experiment.json", "clumps_1");
  CHECK(one.property != "aspect_ratio");
  CHECK(one.max_evaluations == 1);
}

TEST_CASE("aspect-ratio search: a count no candidate matched, matched by the line through its "
          "candidates", "[unit][shape]") {
  WorkflowFile w = testing_twin::TwinWorkflow("unused.csv", {1, 2, 3});
  w.species[0].semi_axes.clear();
  w.species[0].aspect_ratio = {
      .min = 1.0, .max = 3.5, .start = 2.0, .max_evaluations = 6, .enabled = true};
  CalibrationOutcome o;
  o.termination = calibrate::Termination::kBudget;
  o.message = "budget used up before a match within noise";
  const double bound = ConnectedAspectLimit(3, 1.0, 3.5);
  o.value = bound, o.sigma = 0.04;  // the best candidate: the bound, 33.3 ± 1.1 deg
  o.measured = 31, o.uncertainty = 1, o.simulated = 33.3, o.sem = 1.1;
  // The row when the calibration's line was fitted: crossing a ± σ, standard error there.
  auto row_with_line = [&](bool matched, double residual_sigma, double a, double sigma) {
    o.local_crossing.fitted = true;
    o.local_crossing.matched = matched;
    o.local_crossing.residual_sigma = residual_sigma;
    o.local_crossing.message = std::string(matched ? "matched within noise by" : "estimated by") +
                               " a straight line through the candidates";
    TakeLine(a, sigma, &o);
    return ShapeRowOf(w.species[0], 3, o);
  };
  SECTION("a fitted line: its crossing is the count's shape, matched when as precise as u") {
    struct Case {
      bool matched;
      double residual_sigma, a, sigma;
      const char* words;
    };
    for (const Case& c : {Case{true, 0.8, 2.85, 0.03, "matched within noise by a straight line"},
                          Case{false, 1.01, 2.83, 0.013, "estimated by a straight line"}}) {
      INFO(c.words);
      const ShapeSearchRow row = row_with_line(c.matched, c.residual_sigma, c.a, c.sigma);
      CHECK(row.within_noise == c.matched);
      CHECK(row.local_fit);
      CHECK(row.aspect_ratio == c.a);
      CHECK(row.aspect_sigma == c.sigma);
      CHECK_FALSE(row.aspect_at_bound);
      CHECK(row.angle_deg == 31);                       // the line's value at its crossing
      CHECK(row.angle_sem_deg == c.residual_sigma);     // its standard error there, in degrees
      CHECK(row.cost == 0);
      CHECK(row.message.find(c.words) != std::string::npos);
    }
  }
  SECTION("no line: the best candidate") {
    const ShapeSearchRow row = ShapeRowOf(w.species[0], 3, o);
    CHECK_FALSE(row.local_fit);
    CHECK(row.aspect_ratio == bound);
    CHECK(row.aspect_at_bound);
    CHECK(row.angle_deg == 33.3);
    CHECK(row.cost == Approx(2.3 * 2.3));
  }
  SECTION("a candidate matched: no line is taken") {
    o.termination = calibrate::Termination::kWithinNoise;
    o.local_crossing.fitted = true;
    TakeLine(2.5, 0.1, &o);
    CHECK_FALSE(o.by_line);
    CHECK(o.value == bound);
    CHECK(ShapeRowOf(w.species[0], 3, o).within_noise);
  }
}

}  // namespace
}  // namespace demcal::workflow
