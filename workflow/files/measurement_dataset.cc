#include "workflow/files/measurement_dataset.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace demcal::workflow {
namespace {

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) fields.emplace_back();
    else if (c != '\r') fields.back() += c;
  }
  return fields;
}

bool ParseNumber(const std::string& text, double* out) {
  std::istringstream in(text);
  in >> *out;
  return in && (in >> std::ws).eof() && std::isfinite(*out);
}

}  // namespace

bool ReadDatasetMeasurement(const DatasetQuery& q, calibrate::Measurement* out, bool* has_sd,
                            std::string* error) {
  std::ifstream in(q.path);
  if (!in) return *error = q.path + ": cannot read the dataset", false;
  std::string line;
  if (!std::getline(in, line)) return *error = q.path + ": empty dataset", false;
  const std::vector<std::string> header = SplitCsvLine(line);
  auto column = [&](const std::string& name) {
    for (size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return static_cast<int>(k);
    return -1;
  };
  const int material = column("material"), coating = column("coating_PEG_wt_pct");
  const int value = column(q.value_column), sd = column(q.sd_column), source = column("source");
  for (const auto& [name, index] : {std::pair{"material", material}, {"coating_PEG_wt_pct", coating},
                                    {q.value_column.c_str(), value}, {"source", source}})
    if (index < 0) return *error = q.path + ": no column '" + name + "'", false;
  for (int row = 2; std::getline(in, line); ++row) {
    const std::vector<std::string> f = SplitCsvLine(line);
    double c = 0;
    if (f.size() != header.size() || f[material] != q.material || !ParseNumber(f[coating], &c) ||
        std::abs(c - q.coating_PEG_wt_pct) > 1e-9)
      continue;
    const std::string at = q.path + ":" + std::to_string(row) + ": ";
    if (!ParseNumber(f[value], &out->value)) return *error = at + q.value_column + " is not a number", false;
    *has_sd = sd >= 0 && !f[sd].empty();
    if (*has_sd && !(ParseNumber(f[sd], &out->uncertainty) && out->uncertainty > 0))
      return *error = at + q.sd_column + " must be a number > 0 (or empty)", false;
    out->source = q.path + " row " + std::to_string(row) + " (" + f[source] + ")";
    return true;
  }
  std::ostringstream m;
  m << q.path << ": no row with material '" << q.material << "' and coating_PEG_wt_pct "
    << q.coating_PEG_wt_pct;
  return *error = m.str(), false;
}

}  // namespace demcal::workflow
