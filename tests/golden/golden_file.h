#pragma once
// Golden-output files (tests/golden/README.md): a run's key outputs as `field value` lines,
// compared exactly with tests/golden/<case>/expected.txt. Numbers are written in the shortest
// form that reads back to the same double (as result.json and the CSV tables write them), so a
// change in the last bit of a result shows as a difference.
//
//   GoldenValues got;
//   AddJson(ReadJson(out + "/result.json"), "result", {"wall_time_s"}, &got);
//   CheckGolden("aor", got);  // fails naming each differing field, expected and got
//
// With DEMCAL_UPDATE_GOLDEN=1 in the environment, the comparison writes expected.txt instead.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/math/fnv1a.h"
#include "workflow/test_paths.h"

namespace demcal::testing {

// (field, value) in the order the outputs give them.
using GoldenValues = std::vector<std::pair<std::string, std::string>>;

// Every leaf of `j` under `prefix` (objects as `.key`, arrays as `[i]`), in JSON text; a key in
// `ignored` (at any depth) is left out with all below it: wall times, paths, the version.
inline void AddJson(const nlohmann::ordered_json& j, const std::string& prefix,
                    const std::set<std::string>& ignored, GoldenValues* out) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items())
      if (!ignored.count(key)) AddJson(value, prefix + "." + key, ignored, out);
  } else if (j.is_array()) {
    for (size_t k = 0; k < j.size(); ++k)
      AddJson(j[k], prefix + "[" + std::to_string(k) + "]", ignored, out);
  } else {
    out->emplace_back(prefix, j.dump());
  }
}

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline nlohmann::ordered_json ReadOrderedJson(const std::string& path) {
  return nlohmann::ordered_json::parse(ReadText(path));
}

// Every cell of a CSV table (a header line, then rows), as `name[row].column value`; the cells
// are compared as text, which for demcal's tables is the round-trip form of each double.
inline void AddCsv(const std::string& path, const std::string& name, GoldenValues* out) {
  std::istringstream in(ReadText(path));
  std::string line;
  std::vector<std::string> columns;
  for (int row = -1; std::getline(in, line); ++row) {
    std::vector<std::string> cells;
    std::istringstream cells_in(line);
    for (std::string cell; std::getline(cells_in, cell, ',');) cells.push_back(cell);
    if (row < 0) {
      columns = cells;
      continue;
    }
    for (size_t c = 0; c < cells.size(); ++c)
      out->emplace_back(name + "[" + std::to_string(row) + "]." +
                            (c < columns.size() ? columns[c] : std::to_string(c)),
                        cells[c]);
  }
}

// A digest of a whole file (FNV-1a 64 of its bytes), for an output too large to list.
inline void AddDigest(const std::string& path, const std::string& name, GoldenValues* out) {
  std::ostringstream hex;
  hex << std::hex << core::Fnv1a64Of(ReadText(path));
  out->emplace_back(name + ".fnv1a64", hex.str());
}

inline std::string GoldenPath(const std::string& golden_case) {
  return (RepoRoot() / "tests" / "golden" / golden_case / "expected.txt").string();
}

inline void WriteGolden(const std::string& golden_case, const GoldenValues& values) {
  std::ofstream out(GoldenPath(golden_case), std::ios::binary | std::ios::trunc);
  out << "# Golden outputs of the case '" << golden_case << "' (tests/golden/README.md).\n"
      << "# Written by DEMCAL_UPDATE_GOLDEN=1 ./build/tests/demcal_tests '[golden]'; do not "
         "edit.\n";
  for (const auto& [field, value] : values) out << field << " " << value << "\n";
}

inline GoldenValues ReadGolden(const std::string& golden_case) {
  std::istringstream in(ReadText(GoldenPath(golden_case)));
  GoldenValues values;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const size_t space = line.find(' ');
    values.emplace_back(line.substr(0, space),
                        space == std::string::npos ? "" : line.substr(space + 1));
  }
  return values;
}

// "" when `got` equals the golden file of `golden_case`; else what differs (field, expected,
// got; the first 20 fields) and how to accept a change made on purpose.
inline std::string GoldenDifferences(const std::string& golden_case, const GoldenValues& got) {
  const GoldenValues expected = ReadGolden(golden_case);
  if (expected.empty())
    return "no golden outputs in " + GoldenPath(golden_case) +
           "; write them with DEMCAL_UPDATE_GOLDEN=1 ./build/tests/demcal_tests '[golden]'";
  std::map<std::string, std::string> want(expected.begin(), expected.end());
  std::ostringstream diff;
  int differences = 0;
  // One line each for the field, the expected and the value got: Catch wraps messages at 80
  // columns, and a number cut in two would be misread.
  auto note = [&](const std::string& field, const std::string& expected_value,
                  const std::string& got_value) {
    if (++differences <= 20)
      diff << "  " << field << "\n      expected: " << expected_value
           << "\n      got:      " << got_value << "\n";
  };
  for (const auto& [field, value] : got) {
    const auto it = want.find(field);
    if (it == want.end()) {
      note(field, "(not in the golden file)", value);
      continue;
    }
    if (it->second != value) note(field, it->second, value);
    want.erase(it);
  }
  for (const auto& [field, value] : expected)
    if (want.count(field)) note(field, value, "(missing from the outputs)");
  if (differences == 0) return "";
  if (differences > 20) diff << "  ... and " << differences - 20 << " more fields\n";
  return "golden case '" + golden_case + "': " + std::to_string(differences) +
         " field(s) differ from " + GoldenPath(golden_case) + ":\n" + diff.str() +
         "If the change is intended (a physics or output change made on purpose), regenerate "
         "with DEMCAL_UPDATE_GOLDEN=1 ./build/tests/demcal_tests '[golden]' and commit the "
         "new expected.txt with the change (tests/golden/README.md).";
}

inline bool UpdatingGolden() {
  const char* update = std::getenv("DEMCAL_UPDATE_GOLDEN");
  return update != nullptr && std::string(update) == "1";
}

// Under DEMCAL_UPDATE_GOLDEN=1, writes the golden file of `golden_case` from the first outputs
// given for it in this process and returns its path; later outputs of the case (other thread
// counts) are compared with it. "" otherwise.
inline std::string UpdateGoldenOnce(const std::string& golden_case, const GoldenValues& values) {
  static std::set<std::string> written;
  if (!UpdatingGolden() || !written.insert(golden_case).second) return "";
  WriteGolden(golden_case, values);
  return GoldenPath(golden_case);
}

// Compares `values` with the golden file of `golden_case` (rewritten first under
// DEMCAL_UPDATE_GOLDEN=1, see UpdateGoldenOnce); a failure lists what differs.
inline void CheckGolden(const std::string& golden_case, const GoldenValues& values) {
  const std::string written = UpdateGoldenOnce(golden_case, values);
  if (!written.empty()) WARN("wrote " << written);
  const std::string differences = GoldenDifferences(golden_case, values);
  INFO(differences);
  CHECK(differences.empty());
}

}  // namespace demcal::testing
