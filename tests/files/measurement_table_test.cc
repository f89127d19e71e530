// The tidy measurement table (measurement_table.h): the bundled tables load, rows are found by
// observable, material and condition, and bad tables are refused naming the line and column.
#include "files/measurement_table.h"

#include <catch2/catch.hpp>
#include <fstream>

#include "core/io/scratch_dir.h"
#include "workflow/test_paths.h"

using namespace demcal::workflow;
using demcal::testing::RepoRoot;
using demcal::testing::ScratchDir;

namespace {

const char* kHeader = "observable,unit,material,coating_PEG_wt_pct,value,uncertainty,repeats,provenance,source\n";

std::string Load(const ScratchDir& dir, const std::string& rows, MeasurementTable* table = nullptr) {
  std::ofstream(dir.str("t.csv")) << kHeader << rows;
  MeasurementTable t;
  std::string error;
  const bool ok = LoadMeasurementTable(dir.str("t.csv"), table ? table : &t, &error);
  return ok ? "ok" : error;
}

}  // namespace

TEST_CASE("the alizadeh2018 table: Table 1 angles, the inferred 0.5 wt% row, by condition", "[unit]") {
  MeasurementTable table;
  std::string error;
  REQUIRE(LoadMeasurementTable((RepoRoot() / "datasets/alizadeh2018/measurements.csv").string(), &table, &error));
  const MeasurementRow* bp = table.Find("angle_deg", "BP", {{"coating_PEG_wt_pct", "0.0"}}, &error);
  REQUIRE(bp);
  CHECK(bp->value == 40.0);
  CHECK_FALSE(bp->HasUncertainty());
  CHECK(bp->provenance == "measured");
  const MeasurementRow* ep = table.Find("angle_deg", "EP", {{"coating_PEG_wt_pct", "0.5"}}, &error);
  REQUIRE(ep);
  CHECK(ep->provenance == "inferred");
  CHECK(table.Find("angle_deg", "mixture", {}, &error) == nullptr);  // two coating levels
  CHECK_THAT(error, Catch::Contains("2 rows") && Catch::Contains("tells them apart"));
}

TEST_CASE("a value simulated by another engine says so in its provenance", "[unit]") {
  ScratchDir dir("measurement_table_simulated");
  MeasurementTable table;
  const std::string row = "angle_deg,deg,BP,0,17.5,1,4,simulated:liggghts-3.8,scripts/x.py\n";
  REQUIRE(Load(dir, row, &table) == "ok");
  const std::string& p = table.rows[0].provenance;
  std::string engine;
  CHECK(p == "simulated:liggghts-3.8");
  CHECK(IsSimulatedProvenance(p, &engine));
  CHECK(engine == "liggghts-3.8");
  CHECK(IsModelMadeProvenance(p));
  CHECK(IsModelMadeProvenance("synthetic"));
  CHECK_FALSE(IsModelMadeProvenance("measured"));
  CHECK_FALSE(IsModelMadeProvenance("inferred"));
  CHECK_FALSE(IsSimulatedProvenance("synthetic"));
}

TEST_CASE("measurement tables refuse bad rows naming the line and the column", "[unit]") {
  ScratchDir dir("measurement_table");
  const std::string good = "angle_deg,deg,BP,0,40,1,5,measured,Table 1\n";
  CHECK(Load(dir, good) == "ok");
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,400,,,measured,x\n"), Catch::Contains("t.csv:2: value") && Catch::Contains("[0, 90] deg"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,-40,,,measured,x\n"), Catch::Contains("outside"));
  CHECK_THAT(Load(dir, good + "angle_deg,deg,BP,0.0,41,,,measured,y\n"),
             Catch::Contains("t.csv:3") && Catch::Contains("as line 2"));
  CHECK_THAT(Load(dir, "angle_deg,rad,BP,0,0.7,,,measured,x\n"), Catch::Contains("unit"));
  CHECK_THAT(Load(dir, "porosity,-,BP,0,0.4,,,measured,x\n"), Catch::Contains("unknown 'porosity'"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,40,,,guessed,x\n"), Catch::Contains("provenance"));
  for (const char* bad : {"simulated", "simulated:", "simulated:LIGGGHTS", "simulated:lig ghts"})
    CHECK_THAT(Load(dir, std::string("angle_deg,deg,BP,0,40,,,") + bad + ",x\n"),
               Catch::Contains("t.csv:2: provenance") && Catch::Contains("simulated:<engine>"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,40,-1,,measured,x\n"), Catch::Contains("uncertainty"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,nan,,,measured,x\n"),
             Catch::Contains("'nan' is not a finite decimal number"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,40,,,measured,\n"), Catch::Contains("source"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,40,,,measured,\"x\n"), Catch::Contains("quote"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,40\n"), Catch::Contains("4 fields"));
}

TEST_CASE("measurement tables read what a cell shows, nothing the reader would guess", "[unit]") {
  ScratchDir dir("measurement_table_silent");
  // strtod reads 0x1p5 as 32, inside the angle range: refused, not taken as 32 degrees.
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,0x1p5,,,measured,x\n"),
             Catch::Contains("t.csv:2: value: '0x1p5' is not a finite decimal number"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,40,0x1,,measured,x\n"), Catch::Contains("uncertainty"));
  CHECK_THAT(Load(dir, "angle_deg,deg,BP,0,40,,0x5,measured,x\n"), Catch::Contains("repeats"));
  MeasurementTable table;
  REQUIRE(Load(dir, "angle_deg,deg,BP,4.0e1,4.05e1,,,measured,x\n", &table) == "ok");
  CHECK(table.rows[0].value == 40.5);

  // A second 'value' column would win over the first: refused, naming both positions.
  std::ofstream(dir.str("dup.csv")) << "observable,unit,material,value,uncertainty,repeats,"
                                       "provenance,source,value\nangle_deg,deg,BP,40,,,measured,x,41\n";
  std::string error;
  CHECK_FALSE(LoadMeasurementTable(dir.str("dup.csv"), &table, &error));
  CHECK_THAT(error, Catch::EndsWith("dup.csv:1: column 'value' appears twice (columns 4 and 9)"));

  // The UTF-8 byte-order mark spreadsheets write before the header is not part of a column name.
  std::ofstream(dir.str("bom.csv")) << "\xEF\xBB\xBF" << kHeader
                                    << "angle_deg,deg,BP,0,40,,,measured,x\n";
  MeasurementTable with_bom;
  REQUIRE(LoadMeasurementTable(dir.str("bom.csv"), &with_bom, &error));
  REQUIRE(with_bom.rows.size() == 1);
  CHECK(with_bom.rows[0].observable == "angle_deg");
  CHECK(with_bom.rows[0].value == 40);
}
