#include "experiments/discharge/discharge_section.h"

#include <catch2/catch.hpp>
#include <string>

#include "experiments/common/experiment_file.h"
#include "objectives/common/fidelity.h"
#include "workflow/test_paths.h"

using namespace demcal;
using nlohmann::json;

namespace {

// One species of 1 mm spheres and a wall material.
core::Scene Model() {
  core::Scene model;
  model.materials = {{"grain", 1e7, 0.25, 1000}, {"steel", 2e11, 0.3, 7800}};
  core::Species s;
  s.name = "grain";
  s.size.diameter_m = 0.001;
  model.species = {s};
  model.pair_parameters.assign(4, core::PairParameters{});
  return model;
}

json Section() {
  return json::parse(R"({
    "feed": {"components": [{"species": "grain", "mass_fraction": 1}], "mass_kg": 0.002,
             "mass_rate_kg_s": 0.01},
    "hopper": {"top_diameter_m": 0.04, "orifice_diameter_m": 0.008},
    "wall_material": "steel"
  })");
}

// The error of parsing `section`, or "" if it parses.
std::string ErrorOf(const json& section) {
  objectives::DischargeSettings settings;
  std::string error;
  return workflow::ParseDischargeSection(section, "f.json", Model(), &settings, &error) ? "" : error;
}

}  // namespace

TEST_CASE("discharge section: a minimal section parses with the documented defaults", "[unit]") {
  objectives::DischargeSettings s;
  std::string error;
  REQUIRE(workflow::ParseDischargeSection(Section(), "f.json", Model(), &s, &error));
  CHECK(s.fill == objectives::DischargeSettings::Fill::kPour);
  CHECK(s.hopper.orifice_diameter_m == 0.008);
  CHECK(s.hopper.cone_half_angle_deg == 30);
  CHECK(s.wall_material == 1);
  CHECK(s.gate_open_s == 0);  // opens once settled
  CHECK(s.sample_interval_s > 0);
}

TEST_CASE("discharge section: errors name the field and the allowed range", "[unit]") {
  json s = Section();
  s["hopper"]["orifice_diameter_m"] = 0.0025;
  CHECK(ErrorOf(s).find("discharge.hopper.orifice_diameter_m = 0.0025 must exceed 3 largest particle "
                        "diameters") != std::string::npos);
  s = Section();
  s["hopper"]["cone_half_angle_deg"] = 90;
  CHECK(ErrorOf(s).find("discharge.hopper.cone_half_angle_deg") != std::string::npos);
  CHECK(ErrorOf(s).find("(0, 89]") != std::string::npos);
  s = Section();
  s["hoper"] = s["hopper"];
  CHECK(ErrorOf(s).find("hoper") != std::string::npos);
  s = Section();
  s.erase("hopper");
  CHECK(ErrorOf(s).find("discharge.hopper") != std::string::npos);
  s = Section();
  s["fill"] = "pile";
  CHECK(ErrorOf(s).find("discharge.fill") != std::string::npos);
  s = Section();
  s["analysis"] = {{"flow_window_low", 0.8}, {"flow_window_high", 0.3}};
  CHECK(ErrorOf(s).find("discharge.analysis.flow_window_high") != std::string::npos);
  s = Section();
  s["stall_s"] = 0.001;
  CHECK(ErrorOf(s).find("discharge.stall_s") != std::string::npos);
  s = Section();
  s["feed"]["mass_kg"] = 1.0;
  CHECK(ErrorOf(s).find("discharge.feed.mass_kg") != std::string::npos);
  s = Section();
  s["catch_depth_m"] = 0.003;
  CHECK(ErrorOf(s).find("discharge.catch_depth_m") != std::string::npos);
}

TEST_CASE("discharge section: a placed fill needs no pour rate", "[unit]") {
  json s = Section();
  s["fill"] = "place";
  s["feed"].erase("mass_rate_kg_s");
  CHECK(ErrorOf(s).empty());
  s["fill"] = "pour";
  CHECK(ErrorOf(s).find("mass_rate_kg_s") != std::string::npos);
}

TEST_CASE("discharge example: valid at its fidelity and its quick fidelity", "[unit]") {
  workflow::ExperimentFile file;
  std::string error;
  const std::string path = (testing::RepoRoot() / "examples/discharge_funnel.json").string();
  REQUIRE(workflow::LoadExperimentFile(path, &file, &error));
  CHECK(file.experiment == "discharge");
  for (const objectives::Fidelity& fidelity : {file.fidelity, file.quick_fidelity}) {
    core::Scene model = file.model;
    objectives::ApplyFidelity(fidelity, &model);
    objectives::DischargeSettings s;
    INFO(fidelity.name);
    CHECK(workflow::ParseDischargeSection(file.section, file.source, model, &s, &error));
    INFO(error);
  }
}
