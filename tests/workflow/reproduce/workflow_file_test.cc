#include "workflow/reproduce/workflow_file.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "workflow/test_paths.h"

using namespace demcal::workflow;
namespace fs = std::filesystem;

namespace {

const fs::path kBundled = demcal::testing::RepoRoot() / "datasets" / "alizadeh2018" / "workflow.json";

nlohmann::json Bundled() {
  std::ifstream in(kBundled);
  return nlohmann::json::parse(in);
}

// Writes `doc` beside the bundled file (so its relative paths still resolve) and loads it.
bool LoadVariant(const nlohmann::json& doc, WorkflowFile* out, std::string* error) {
  const fs::path path = kBundled.parent_path() / ".workflow_file_test.json";
  std::ofstream(path) << doc.dump(2);
  const bool ok = LoadWorkflowFile(path.string(), out, error);
  fs::remove(path);
  return ok;
}

// One valid segregation.pair_overrides entry with `key` set to `value` (null: left out).
void SetOverride(nlohmann::json& d, const std::string& key, const nlohmann::json& value) {
  nlohmann::json o = {{"materials", nlohmann::json::array({"EP", "BP"})},
                      {"property", "rolling_friction"},
                      {"value", 0.25},
                      {"note", "n"}};
  if (value.is_null())
    o.erase(key);
  else
    o[key] = value;
  d["segregation"]["pair_overrides"] = nlohmann::json::array({o});
}

}  // namespace

TEST_CASE("the bundled alizadeh2018 workflow loads with its paths resolved", "[unit]") {
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile(kBundled.string(), &w, &error));
  CHECK(w.name == "alizadeh2018");
  CHECK(w.species.size() == 3);
  CHECK(fs::exists(w.species[0].experiment_file));
  CHECK(fs::exists(w.synthetic_measurements));
  CHECK(w.coating.levels == std::vector<double>{0.5, 1.5, 2.5, 3.5});
  CHECK(w.coating.curve_form == demcal::calibrate::CurveForm::kLinear);
  CHECK(w.cohesion.gamma_J_m2 == Approx(0.086));
  CHECK(w.reference.size() >= 30);
  CHECK(w.segregation.size_scale == 4);  // the bundled workflow's choice, docs/reproduce.md
  CHECK(ResolveWorkflowName("alizadeh2018", demcal::testing::RepoRoot().string()).ends_with(
      "datasets/alizadeh2018/workflow.json"));
  CHECK(ResolveWorkflowName("my/flow.json", "") == "my/flow.json");
}

TEST_CASE("workflow file errors name the file, the key and the allowed values", "[unit]") {
  WorkflowFile w;
  std::string error;
  struct Case {
    std::function<void(nlohmann::json&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](nlohmann::json& d) { d["format"] = "demcal-workflow/9"; }, "format"},
      {[](nlohmann::json& d) { d.erase("shape_assumption"); }, "shape_assumption"},
      {[](nlohmann::json& d) { d["coating"]["levels_wt_pct"][2] = -1; },
       "coating.levels_wt_pct[2]: must be in (0, 100]"},
      {[](nlohmann::json& d) { d["coating"]["curve_form"] = "cubic"; }, "coating.curve_form"},
      {[](nlohmann::json& d) {
         d["species"][1]["min"] = 2;
         d["species"][1]["max"] = 1;
       },
       "species[1].start"},
      {[](nlohmann::json& d) { d["species"][0]["experiment_file"] = "missing.json"; }, "not found"},
      {[](nlohmann::json& d) { d["cohesion"]["poisson_ratio"] = 0.7; }, "cohesion.poisson_ratio"},
      {[](nlohmann::json& d) { d["reference"][0]["key"] = "nonsense"; }, "reference[0].key"},
      {[](nlohmann::json& d) { d["coating"]["partner_radii_m"] = {1e-4}; },
       "one radius per partner"},
      {[](nlohmann::json& d) { d["segregation"]["replicates"] = 0; }, "segregation.replicates"},
      {[](nlohmann::json& d) { d["segregation"].erase("stiffness_scale"); },
       "segregation.stiffness_scale' must be given together with size_scale"},
      {[](nlohmann::json& d) { d["segregation"]["size_scale"] = 0.5; }, "segregation.size_scale"},
      {[](nlohmann::json& d) {
         d["segregation"]["funnel_orifice"] = {{"effective_orifice_diameter_m", -0.01},
                                               {"beverloo_k", 0.5}, {"note", "n"}};
       },
       "segregation.funnel_orifice.effective_orifice_diameter_m"},
      {[](nlohmann::json& d) {
         d["segregation"]["funnel_orifice"] = {{"effective_orifice_diameter_m", 0.012},
                                               {"beverloo_k", 4}, {"note", "n"}};
       },
       "segregation.funnel_orifice.beverloo_k"},
      {[](nlohmann::json& d) {
         d["segregation"]["funnel_orifice"] = {{"effective_orifice_diameter_m", 0.012},
                                               {"beverloo_k", 0.5}};
       },
       "segregation.funnel_orifice.note"},
      {[](nlohmann::json& d) { SetOverride(d, "materials", nlohmann::json::array({"EP"})); },
       "segregation.pair_overrides[0].materials' must be two material names"},
      {[](nlohmann::json& d) { SetOverride(d, "property", "restitution"); },
       "segregation.pair_overrides[0].property"},
      {[](nlohmann::json& d) { SetOverride(d, "value", 20); }, "segregation.pair_overrides[0].value"},
      {[](nlohmann::json& d) { SetOverride(d, "note", nullptr); },
       "segregation.pair_overrides[0].note"},
      {[](nlohmann::json& d) { d["unexpected"] = 1; }, "unexpected"},
  };
  for (const Case& c : cases) {
    nlohmann::json doc = Bundled();
    c.edit(doc);
    INFO(c.expected);
    CHECK_FALSE(LoadVariant(doc, &w, &error));
    CHECK(error.find(".workflow_file_test.json") != std::string::npos);
    CHECK(error.find(c.expected) != std::string::npos);
  }
}

TEST_CASE("a workflow file that is not JSON is refused with its line", "[unit]") {
  const fs::path path = fs::temp_directory_path() / "demcal_bad_workflow.json";
  std::ofstream(path) << "{\n  \"format\": \n";
  WorkflowFile w;
  std::string error;
  CHECK_FALSE(LoadWorkflowFile(path.string(), &w, &error));
  CHECK(error.find("demcal_bad_workflow.json") != std::string::npos);
  fs::remove(path);
}

TEST_CASE("the clumps workflow calibrates each species' aspect ratio; bad ones are refused",
          "[unit]") {
  const fs::path clumps = kBundled.parent_path() / "workflow_clumps.json";
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadWorkflowFile(clumps.string(), &w, &error));
  for (const WorkflowSpecies& s : w.species) {
    INFO(s.name);
    CHECK(s.hold);
    CHECK(s.aspect_ratio.enabled);
    CHECK(s.aspect_ratio.min == 1.0);
    CHECK(s.aspect_ratio.max == 3.5);
    CHECK(s.aspect_ratio.max_evaluations == 8);
    CHECK(s.semi_axes.empty());  // the shape is calibrated, not given
  }
  std::ifstream in(clumps);
  const nlohmann::json base = nlohmann::json::parse(in);
  struct Case {
    std::function<void(nlohmann::json&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](nlohmann::json& a) { a["min"] = 0.5; },
       "aspect_ratio.min' = 0.5 is outside the allowed range [1, 10]"},
      {[](nlohmann::json& a) { a["max"] = 12; },
       "aspect_ratio.max' = 12 is outside the allowed range [1, 10]"},
      {[](nlohmann::json& a) { a["max"] = 1.0; }, "aspect_ratio.max' must be larger than min"},
      {[](nlohmann::json& a) { a["start"] = 4; },
       "aspect_ratio.start' = 4 is outside the allowed range [1, 3.5]"},
      {[](nlohmann::json& a) { a["max_evaluations"] = 2; },
       "aspect_ratio.max_evaluations' = 2 is outside the allowed range [3, 30]"},
      {[](nlohmann::json& a) { a["aspect"] = 2; }, "aspect_ratio"},
      // No 2-sphere chain in [1, 1.05] stands apart (aspect_bounds.h: from a ≈ 1.057).
      {[](nlohmann::json& a) { a["max"] = 1.05, a["start"] = 1.02; },
       "aspect_ratio' [min, max] = [1, 1.05] holds no grain of 2 spheres: it must overlap [1.05"},
  };
  for (const Case& c : cases) {
    nlohmann::json doc = base;
    c.edit(doc["species"][0]["aspect_ratio"]);
    INFO(c.expected);
    CHECK_FALSE(LoadVariant(doc, &w, &error));
    CHECK(error.find(".workflow_file_test.json") != std::string::npos);
    CHECK(error.find("species[0]." + c.expected) != std::string::npos);
  }
  nlohmann::json both = base;
  both["species"][0]["semi_axes"] = {2, 1, 1};
  CHECK_FALSE(LoadVariant(both, &w, &error));
  CHECK(error.find("species[0].semi_axes' give either semi_axes") != std::string::npos);
  nlohmann::json free = base;
  free["species"][0]["hold"] = false;
  CHECK_FALSE(LoadVariant(free, &w, &error));
  CHECK(error.find("species[0].aspect_ratio' needs clump_counts and \"hold\": true") !=
        std::string::npos);
}

TEST_CASE("segregation.pair_overrides are read in order with their note", "[unit]") {
  nlohmann::json doc = Bundled();
  doc["segregation"]["pair_overrides"] = {{{"materials", {"BP", "EP"}},
                                           {"property", "rolling_friction"},
                                           {"value", 0.25},
                                           {"note", "bracket"}},
                                          {{"materials", {"EP", "TAED"}},
                                           {"property", "sliding_friction"},
                                           {"value", 0.4},
                                           {"note", "n"}}};
  WorkflowFile w;
  std::string error;
  REQUIRE(LoadVariant(doc, &w, &error));
  REQUIRE(w.segregation.pair_overrides.size() == 2);
  const PairOverride& o = w.segregation.pair_overrides[0];
  CHECK(o.material_a == "BP");
  CHECK(o.material_b == "EP");
  CHECK(o.property == "rolling_friction");
  CHECK(o.value == 0.25);
  CHECK(o.note == "bracket");
  CHECK(w.segregation.pair_overrides[1].property == "sliding_friction");
}
