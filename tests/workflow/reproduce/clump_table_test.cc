// Stage 1's Fig. 3 table read from a clump-count calibration's own files (clump_count.json and
// clumps_<n>/result.json), and the nearest count used when none matches.
#include "workflow/reproduce/clump_table.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "core/io/scratch_dir.h"

namespace demcal::workflow {
namespace {

void Write(const std::string& path, const nlohmann::json& j) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << j.dump();
}

TEST_CASE("clump table: angle, sem and cost per count from the loop's files", "[unit]") {
  testing::ScratchDir dir("clump_table");
  Write(dir.str("clump_count.json"),
        {{"note", "no count matched every target within noise"},
         {"counts",
          {{{"count", 1}, {"cost", 466.0}, {"within_noise", false}, {"agrees", false},
            {"termination", "budget"}},
           {{"count", 2}, {"cost", 5.1}, {"within_noise", false}, {"agrees", false},
            {"termination", "budget"}},
           {{"count", 3}, {"cost", nullptr}, {"within_noise", false}, {"agrees", false},
            {"termination", "failed"}}}}});
  Write(dir.str("clumps_1/result.json"),
        {{"targets", {{{"simulated", 18.67}, {"sem", 0.74}}}}});
  Write(dir.str("clumps_2/result.json"),
        {{"targets", {{{"simulated", 29.8}, {"sem", 4.49}}}}});
  // clumps_3 has no result.json: its numbers stay null.
  const nlohmann::json table = ReadClumpCountTable(dir.str());
  CHECK(table["note"] == "no count matched every target within noise");
  REQUIRE(table["rows"].size() == 3);
  CHECK(table["rows"][0]["angle_deg"] == 18.67);
  CHECK(table["rows"][1]["angle_sem_deg"] == 4.49);
  CHECK(table["rows"][2]["angle_deg"].is_null());
  CHECK(table["rows"][2]["cost"].is_null());
  // The nearest count is the least cost among the rows that have one.
  CHECK(NearestClumpRow(table["rows"])["count"] == 2);
  CHECK(NearestClumpRow(nlohmann::json::array()).is_null());
  // No loop ran: no rows.
  testing::ScratchDir empty("clump_table_empty");
  CHECK(ReadClumpCountTable(empty.str())["rows"].empty());
}

}  // namespace
}  // namespace demcal::workflow
