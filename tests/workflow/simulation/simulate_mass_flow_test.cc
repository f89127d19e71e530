// demcal simulate with sinks: mass_flow.csv (outputs/mass_flow_log.h) and the sink
// tallies of summary.json, on a small version of examples/silo_discharge.json.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "outputs/exit_codes.h"
#include "workflow/test_paths.h"
#include "workflow/tiny_scene.h"

using namespace demcal::workflow;
using demcal::testing::ReadJson;
using demcal::testing::ScratchDir;
using demcal::testing::SimulateQuietly;
using nlohmann::json;

namespace {

std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::istringstream s(line);
    std::string f;
    while (std::getline(s, f, ',')) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

}  // namespace

TEST_CASE("simulate writes the discharged mass over time of a silo with a sink", "[unit]") {
  json d = json::parse(
      std::ifstream((demcal::testing::RepoRoot() / "examples" / "silo_discharge.json").string()));
  d["fills"][0]["count"] = 300;
  d["walls"][2]["remove_at_s"] = 0.03;
  d["time"] = {{"duration_s", 0.25}, {"timestep_s", 2e-5}};  // rows exactly every 500 steps
  d["output"]["vtk_interval_s"] = 0.25;
  ScratchDir dir("simulate_mass_flow");
  REQUIRE(SimulateQuietly(dir, d, /*threads=*/1) == kExitOk);

  const json s = ReadJson(dir.str("out/summary.json"));
  CHECK(s["outputs"]["mass_flow_csv"] == "mass_flow.csv");
  REQUIRE(s["sinks"].size() == 2);
  CHECK(s["sinks"][0]["name"] == "outlet");
  CHECK(s["sinks"][1]["name"] == "domain");
  const double removed = s["sinks"][0]["removed_mass_kg"].get<double>();
  CHECK(removed > 0);
  CHECK(s["sinks"][0]["per_species"][0]["species"] == "beads");

  const auto rows = ReadCsv(dir.str("out/mass_flow.csv"));
  REQUIRE(rows.size() == 27);  // header, t = 0, every 0.01 s to 0.25 s
  const std::vector<std::string> header = {
      "time_s",
      "sink.outlet.beads.removed_count",
      "sink.outlet.beads.removed_mass_kg",
      "sink.domain.beads.removed_count",
      "sink.domain.beads.removed_mass_kg",
      "plane.orifice.beads.mass_beyond_kg"};
  CHECK(rows[0] == header);
  double last = 0;
  for (size_t r = 1; r < rows.size(); ++r) {
    const double t = std::stod(rows[r][0]), mass = std::stod(rows[r][2]);
    CHECK(t == Approx(0.01 * (r - 1)).margin(1e-9));
    CHECK(mass >= last);  // cumulative
    if (t < 0.03) CHECK(std::stod(rows[r][5]) == 0);  // plugged: nothing below the orifice
    last = mass;
  }
  CHECK(last == Approx(removed).epsilon(1e-12));
}
