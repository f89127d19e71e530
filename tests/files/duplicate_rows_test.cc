// FirstDuplicateRow (files/duplicate_rows.h): the same pair a check of every row against every
// earlier one finds, on random tables built to hold near-equal numbers; and a large table loads
// in a time a pairwise check could not come near.
#include "files/duplicate_rows.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>

#include "core/io/scratch_dir.h"

using namespace demcal::workflow;
using demcal::testing::ScratchDir;

namespace {

std::optional<std::pair<size_t, size_t>> PairwiseFirstDuplicate(
    const std::vector<MeasurementRow>& rows) {
  for (size_t j = 1; j < rows.size(); ++j)
    for (size_t i = 0; i < j; ++i)
      if (SameRowKey(rows[i], rows[j])) return std::make_pair(i, j);
  return std::nullopt;
}

// A cell drawn from a few numbers, the same numbers written otherwise or moved by 1e-13 to 1e-11
// relative (some inside SameConditionCell's 1e-12, some outside), a word, or nothing.
std::string RandomCell(std::mt19937& rng) {
  static const double kBase[] = {0.0, 0.5, 1.0, 1e6, -3.25};
  const double base = kBase[rng() % 5];
  char text[64];
  switch (rng() % 6) {
    case 0: std::snprintf(text, sizeof text, "%.17g", base); break;
    case 1: std::snprintf(text, sizeof text, "%.3e", base); break;
    case 2: std::snprintf(text, sizeof text, "%.17g", base + 3e-13 * (1 + std::abs(base))); break;
    case 3: std::snprintf(text, sizeof text, "%.17g", base + 1.5e-12 * (1 + std::abs(base))); break;
    case 4: return rng() % 2 ? "slot" : "drum";
    default: return "";
  }
  return text;
}

}  // namespace

TEST_CASE("FirstDuplicateRow finds the pair a pairwise check finds", "[unit]") {
  std::mt19937 rng(20261204);
  for (int table = 0; table < 400; ++table) {
    std::vector<MeasurementRow> rows(2 + rng() % 40);
    for (size_t k = 0; k < rows.size(); ++k) {
      MeasurementRow& row = rows[k];
      row.line = static_cast<int>(k) + 2;
      row.observable = rng() % 4 ? "angle_deg" : "porosity";
      row.material = rng() % 3 ? "BP" : "EP";
      for (const char* column : {"coating_PEG_wt_pct", "diameter_m", "test"})
        if (std::string cell = RandomCell(rng); !cell.empty()) row.conditions[column] = cell;
    }
    INFO("table " << table);
    CHECK(FirstDuplicateRow(rows) == PairwiseFirstDuplicate(rows));
  }
}

TEST_CASE("a measurement table of 200 thousand distinct rows loads quickly", "[unit]") {
  // 200,000 rows: 2e10 row pairs for a check of each row against every earlier one, hours at
  // any speed; the sorted check does a few million comparisons. Loading takes about half a
  // second in Release (measured: the parsing dominates), so the 20 s bound is a 40x margin for
  // slow or sanitized builds while a quadratic check would exceed it by orders of magnitude.
  ScratchDir dir("measurement_table_large");
  const std::string path = dir.str("large.csv");
  {
    std::ofstream out(path);
    out << "observable,unit,material,coating_PEG_wt_pct,diameter_m,value,uncertainty,repeats,"
           "provenance,source\n";
    for (int k = 0; k < 200000; ++k)
      out << "angle_deg,deg,BP," << k % 1000 << "," << 0.001 * (1 + k / 1000)
          << ",40,1,5,synthetic,generated\n";
  }
  const auto start = std::chrono::steady_clock::now();
  MeasurementTable table;
  std::string error;
  const bool loaded = LoadMeasurementTable(path, &table, &error);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(error);
  REQUIRE(loaded);
  CHECK(table.rows.size() == 200000);
  CHECK(elapsed_s < 20.0);

  // The same table with its last row repeating the first: refused, naming both lines.
  std::ofstream(path, std::ios::app) << "angle_deg,deg,BP,0,0.001,41,,,synthetic,generated\n";
  MeasurementTable again;
  CHECK_FALSE(LoadMeasurementTable(path, &again, &error));
  CHECK_THAT(error, Catch::Contains("large.csv:200002: the same observable, material and "
                                    "conditions as line 2"));
}
