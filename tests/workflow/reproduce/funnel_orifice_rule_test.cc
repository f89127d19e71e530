// The workflow's own funnel orifice rule (segregation.funnel_orifice): grains that meter
// differently from those the experiment file's rule was fitted on (the calibrated clumps against
// the spheres) get the rule the workflow names, D = effective + k d_max at every fidelity
// (experiments/segregation/funnel_geometry.h); the edited copy must still parse, keep the
// funnel's other dimensions, and a file without a funnel must be refused, not given one.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "experiments/segregation/segregation_section.h"
#include "objectives/common/feed.h"
#include "objectives/common/fidelity.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/segregation_example.h"
#include "workflow/reproduce/workflow_file.h"
#include "workflow/test_paths.h"

namespace demcal::workflow {
namespace {

nlohmann::ordered_json Example() { return testing_support::SegregationExample(); }

// The funnel of the edited copy as the experiment reader parses it, at size `size_scale`, and
// the orifice it opens for the copy's feed.
struct Parsed {
  objectives::FunnelSettings funnel;
  double orifice_m = 0;
};

Parsed Parse(const nlohmann::ordered_json& e, double size_scale) {
  ExperimentFile file;
  std::string error;
  const bool parsed = ParseEditedExperiment(e, "copy.json", &file, &error);
  INFO(error);
  REQUIRE(parsed);
  objectives::Fidelity f = file.fidelity;
  f.size_scale = size_scale;
  core::Scene model = file.model;
  objectives::ApplyFidelity(f, &model);
  objectives::SegregationSettings settings;
  const bool section = ParseSegregationSection(file.section, "copy.json", model, &settings, &error);
  INFO(error);
  REQUIRE(section);
  return {settings.funnel,
          settings.funnel.OrificeDiameterM(FeedMaxMeanCaliperDiameter(model, settings.feed))};
}

}  // namespace

TEST_CASE("the workflow's orifice rule replaces the file's and keeps the funnel's shape",
          "[unit]") {
  nlohmann::ordered_json e = Example();
  const Parsed before = Parse(e, 5);
  REQUIRE(SetFunnelOrificeRule(&e, 0.0132, 0.4));
  const Parsed after = Parse(e, 5);
  CHECK(after.funnel.ScalesWithFidelity());
  CHECK(after.funnel.effective_orifice_diameter_m == 0.0132);
  CHECK(after.funnel.beverloo_k == 0.4);
  CHECK(after.funnel.top_diameter_m == before.funnel.top_diameter_m);
  CHECK(after.funnel.height_m == before.funnel.height_m);
  // Spheres: d_max is TAED's 1 mm sieve edge times the size scale; both orifices pass the jam
  // rule D > 3 d_max (15 and 12 mm).
  CHECK(after.orifice_m == Approx(0.0132 + 0.4 * 0.005));
  CHECK(Parse(e, 4).orifice_m == Approx(0.0132 + 0.4 * 0.004));
}

TEST_CASE("the workflow's orifice rule replaces a fixed orifice; no funnel is refused", "[unit]") {
  nlohmann::ordered_json fixed = Example();
  auto& funnel = fixed["segregation"]["funnel"];
  funnel.erase("effective_orifice_diameter_m");
  funnel.erase("beverloo_k");
  funnel["orifice_diameter_m"] = 0.02;
  REQUIRE(SetFunnelOrificeRule(&fixed, 0.013, 0.5));
  CHECK(Parse(fixed, 5).orifice_m == Approx(0.013 + 0.5 * 0.005));

  nlohmann::ordered_json none = Example();
  none["segregation"]["funnel"] = false;
  const nlohmann::ordered_json unchanged = none;
  CHECK_FALSE(SetFunnelOrificeRule(&none, 0.012, 0.5));
  CHECK(none == unchanged);
}

// The clumps workflow's rule opens the orifice measured to meter its calibrated clumps at the
// quick fidelity: 15.3 mm at size x5 for the shapes of the quick run of 2026-12-07 (TAED's
// 3-sphere clump at a = 2.65 is the feed's widest grain), where the uncoated and the coated heaps
// both drain at about 10 g/s; at 15.6 mm the coated heaps passed the whole feed, at 15.75 mm the
// uncoated too (bench/clump_funnel.py, docs/experiments/segregation_funnel.md). A shape calibrated differently moves the orifice by
// half the change of that grain's mean caliper diameter.
TEST_CASE("the clumps workflow's orifice rule gives the measured 15.3 mm for its clumps at x5",
          "[unit]") {
  WorkflowFile w;
  std::string error;
  const std::string path =
      (testing::RepoRoot() / "datasets/alizadeh2018/workflow_clumps.json").string();
  REQUIRE(LoadWorkflowFile(path, &w, &error));
  REQUIRE(w.segregation.funnel_effective_orifice_diameter_m > 0);
  CHECK_FALSE(w.segregation.funnel_note.empty());
  nlohmann::ordered_json e = Example();
  REQUIRE(SetFunnelOrificeRule(&e, w.segregation.funnel_effective_orifice_diameter_m,
                               w.segregation.funnel_beverloo_k));
  SetSpeciesClump(&e, "BP", {2.305, 1, 1}, 3);
  SetSpeciesClump(&e, "TAED", {2.646, 1, 1}, 3);
  SetSpeciesClump(&e, "EP", {1.057, 1, 1}, 2);
  CHECK(Parse(e, 5).orifice_m == Approx(0.0153).margin(5e-5));
  CHECK(Parse(e, 4).orifice_m > 0.012);  // parsed: the jam rule holds at the default fidelity too
}

}  // namespace demcal::workflow
