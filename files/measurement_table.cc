#include "files/measurement_table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "calibrate/condition.h"
#include "calibrate/observable_registry.h"
#include "files/duplicate_rows.h"
#include "files/input_file.h"

namespace demcal::workflow {
namespace {

const std::set<std::string> kFixedColumns = {"observable", "unit", "material", "value",
                                             "uncertainty", "repeats", "provenance", "source"};

// RFC 4180 fields: commas inside double quotes, "" for a quote. False for an unclosed quote.
bool SplitCsvLine(const std::string& line, std::vector<std::string>* fields) {
  fields->assign(1, "");
  bool quoted = false;
  for (size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (c == '"' && quoted && k + 1 < line.size() && line[k + 1] == '"') fields->back() += '"', ++k;
    else if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) fields->emplace_back();
    else if (c != '\r') fields->back() += c;
  }
  return !quoted;
}

bool ParseNumber(const std::string& text, double* out) {
  std::string trimmed = text;
  while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
  return calibrate::ParseConditionNumber(trimmed, out);
}

class RowReader {
 public:
  RowReader(const std::string& at, std::string* error) : at_(at), error_(error) {}
  bool Fail(const std::string& column, const std::string& problem) {
    *error_ = at_ + column + ": " + problem;
    return false;
  }
  bool Parse(const std::map<std::string, std::string>& cells, MeasurementRow* row) {
    row->observable = cells.at("observable");
    row->unit = cells.at("unit");
    row->material = cells.at("material");
    row->provenance = cells.at("provenance");
    row->source = cells.at("source");
    const calibrate::ObservableInfo* info = calibrate::FindObservable(row->observable);
    if (!info) return Fail("observable", "unknown '" + row->observable + "'; allowed: " + Known());
    if (row->unit != info->unit) return Fail("unit", "'" + row->unit + "' but " + row->observable + " is in " + info->unit);
    if (row->material.empty()) return Fail("material", "empty");
    if (row->source.empty()) return Fail("source", "empty: every value says where it came from");
    const std::string& p = row->provenance;
    if (p != "measured" && p != "inferred" && p != "synthetic" && !IsSimulatedProvenance(p))
      return Fail("provenance", "'" + p + "'; allowed: measured, inferred, synthetic, " +
                                    "simulated:<engine> (engine: 1 to 40 of a-z, 0-9, . - _)");
    if (!ParseNumber(cells.at("value"), &row->value))
      return Fail("value", "'" + cells.at("value") + "' is not a finite decimal number");
    if (!info->Contains(row->value))
      return Fail("value", std::to_string(row->value) + " is outside " + info->RangeText());
    const std::string& u = cells.at("uncertainty");
    // The floor keeps every χ² term finite (objectives/common/input_limits.h).
    if (!u.empty() && !(ParseNumber(u, &row->uncertainty) &&
                        row->uncertainty >= info->MinUncertainty() &&
                        row->uncertainty <= info->max - info->min))
      return Fail("uncertainty", "'" + u + "'; allowed: empty or a number in " +
                                     info->UncertaintyRangeText());
    const std::string& n = cells.at("repeats");
    double repeats = 0;
    if (!n.empty() && !(ParseNumber(n, &repeats) && repeats >= 1 && repeats <= 1e6 &&
                        repeats == std::floor(repeats)))
      return Fail("repeats", "'" + n + "'; allowed: empty or a whole number in [1, 1000000]");
    row->repeats = static_cast<int>(repeats);
    return true;
  }

 private:
  static std::string Known() {
    std::string names;
    for (const std::string& n : calibrate::ObservableNames()) names += (names.empty() ? "" : ", ") + n;
    return names;
  }
  std::string at_;
  std::string* error_;
};

}  // namespace

bool IsSimulatedProvenance(const std::string& provenance, std::string* engine) {
  static const std::string kPrefix = "simulated:";
  if (provenance.rfind(kPrefix, 0) != 0) return false;
  const std::string name = provenance.substr(kPrefix.size());
  // Lower case only, so one engine is spelled one way and rows group by it.
  if (name.empty() || name.size() > 40) return false;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_'))
      return false;
  if (engine) *engine = name;
  return true;
}

bool IsModelMadeProvenance(const std::string& provenance) {
  return provenance == "synthetic" || IsSimulatedProvenance(provenance);
}

bool LoadMeasurementTable(const std::string& path, MeasurementTable* out, std::string* error) {
  // A bench dataset is kilobytes; the cap refuses a runaway file, and the type check a directory
  // or FIFO, before a byte is read.
  std::string text;
  if (!ReadInputFile(path, "measurement table", kMaxTableInputBytes, &text, error)) return false;
  // Spreadsheets write a UTF-8 byte-order mark before the header; it is not part of the first
  // column's name.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  std::istringstream in(std::move(text));
  out->path = path;
  std::string line;
  std::vector<std::string> header, fields;
  if (!std::getline(in, line) || !SplitCsvLine(line, &header))
    return *error = path + ":1: no header line", false;
  // A repeated column would be read as its last copy, the earlier one silently dropped.
  std::map<std::string, size_t> first_position;
  for (size_t k = 0; k < header.size(); ++k) {
    const auto [it, added] = first_position.emplace(header[k], k + 1);
    if (!added)
      return *error = path + ":1: column '" + header[k] + "' appears twice (columns " +
                      std::to_string(it->second) + " and " + std::to_string(k + 1) + ")",
             false;
  }
  for (const std::string& column : kFixedColumns)
    if (std::find(header.begin(), header.end(), column) == header.end())
      return *error = path + ":1: missing column '" + column + "'", false;
  for (const std::string& column : header)
    if (!kFixedColumns.count(column)) out->condition_columns.push_back(column);
  // Rows are read to the end (or the first malformed line) and then checked for repeats all at
  // once, sorted: a repeat before the malformed line is still the error reported, as it would be
  // by a check line by line.
  std::string row_error;
  for (int n = 2; std::getline(in, line); ++n) {
    if (line.empty() || line == "\r") continue;
    const std::string at = path + ":" + std::to_string(n) + ": ";
    if (!SplitCsvLine(line, &fields)) {
      row_error = at + "unclosed double quote";
      break;
    }
    if (fields.size() != header.size()) {
      row_error = at + std::to_string(fields.size()) + " fields, the header has " +
                  std::to_string(header.size());
      break;
    }
    std::map<std::string, std::string> cells;
    for (size_t k = 0; k < header.size(); ++k) cells[header[k]] = fields[k];
    MeasurementRow row;
    row.line = n;
    if (!RowReader(at, &row_error).Parse(cells, &row)) break;
    for (const std::string& column : out->condition_columns)
      if (!cells[column].empty()) row.conditions[column] = cells[column];
    out->rows.push_back(std::move(row));
  }
  if (const auto repeat = FirstDuplicateRow(out->rows)) {
    const MeasurementRow& earlier = out->rows[repeat->first];
    const MeasurementRow& row = out->rows[repeat->second];
    return *error = path + ":" + std::to_string(row.line) + ": " +
                    "the same observable, material and conditions as line " +
                    std::to_string(earlier.line) + " (" + row.observable + ", " + row.material +
                    ", " + calibrate::DescribeCondition(row.conditions) +
                    "): one value per condition", false;
  }
  if (!row_error.empty()) return *error = row_error, false;
  if (out->rows.empty()) return *error = path + ": no rows", false;
  return true;
}

const MeasurementRow* MeasurementTable::Find(const std::string& observable, const std::string& material,
                                             const std::map<std::string, std::string>& conditions,
                                             std::string* error) const {
  std::vector<const MeasurementRow*> hits;
  for (const MeasurementRow& row : rows) {
    if (row.observable != observable || row.material != material) continue;
    bool match = true;
    for (const auto& [column, cell] : conditions) {
      auto it = row.conditions.find(column);
      match = match && it != row.conditions.end() && calibrate::SameConditionCell(it->second, cell);
    }
    if (match) hits.push_back(&row);
  }
  const std::string what = observable + " of " + material +
                           (conditions.empty() ? "" : " at " + calibrate::DescribeCondition(conditions));
  if (hits.empty()) return *error = path + ": no row with " + what, nullptr;
  if (hits.size() > 1)
    return *error = path + ": " + std::to_string(hits.size()) + " rows with " + what + " (lines " +
                    std::to_string(hits[0]->line) + ", " + std::to_string(hits[1]->line) +
                    "); add the condition that tells them apart", nullptr;
  return hits[0];
}

}  // namespace demcal::workflow
