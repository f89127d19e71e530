#include "workflow/reproduce/clump_table.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "files/json_document.h"

namespace demcal::workflow {
namespace {

nlohmann::json NumberOrNull(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key] : nlohmann::json();
}

std::string Fmt(const nlohmann::json& j, const char* format) {
  if (!j.is_number()) return "–";
  char text[48];
  std::snprintf(text, sizeof(text), format, j.get<double>());
  return text;
}

}  // namespace

nlohmann::json ReadClumpCountTable(const std::string& dir) {
  nlohmann::json loop, table = {{"rows", nlohmann::json::array()}, {"note", ""}};
  std::string error;
  if (!std::filesystem::exists(dir + "/clump_count.json") ||
      !ReadJsonFile(dir + "/clump_count.json", "clump-count table", &loop, &error) ||
      !loop.contains("counts") || !loop["counts"].is_array())
    return table;
  table["note"] = loop.value("note", "");
  for (const nlohmann::json& row : loop["counts"]) {
    nlohmann::json out = {{"count", row.value("count", 0)},
                          {"angle_deg", nullptr},
                          {"angle_sem_deg", nullptr},
                          {"cost", NumberOrNull(row, "cost")},
                          {"within_noise", row.value("within_noise", false)},
                          {"agrees", row.value("agrees", false)},
                          {"termination", row.value("termination", "")}};
    const std::string result = dir + "/clumps_" + std::to_string(out["count"].get<int>()) +
                               "/result.json";
    nlohmann::json r;
    if (std::filesystem::exists(result) && ReadJsonFile(result, "calibration result", &r, &error) &&
        r.contains("targets") && r["targets"].is_array() && !r["targets"].empty()) {
      out["angle_deg"] = NumberOrNull(r["targets"][0], "simulated");
      out["angle_sem_deg"] = NumberOrNull(r["targets"][0], "sem");
    }
    table["rows"].push_back(out);
  }
  return table;
}

nlohmann::json NearestClumpRow(const nlohmann::json& rows) {
  nlohmann::json best;
  for (const nlohmann::json& row : rows)
    if (row["cost"].is_number() && (best.is_null() || row["cost"] < best["cost"])) best = row;
  return best;
}

namespace {

// The table of a clump-count loop with a fixed shape (the calibration layer's).
HtmlTable CountTable(const std::string& species, const nlohmann::json& rows) {
  HtmlTable t{.caption = species + ": clump sphere count against the measured angle (the "
                         "paper's Fig. 3)",
              .header = {"spheres", "angle demcal [deg]", "cost (Σ z²)", "within noise",
                         "not excluded", "termination"}};
  for (const nlohmann::json& row : rows) {
    const nlohmann::json sem = row.value("angle_sem_deg", nlohmann::json());
    t.rows.push_back({std::to_string(row.value("count", 0)),
                      Fmt(row.value("angle_deg", nlohmann::json()), "%.1f") +
                          (sem.is_number() ? " ± " + Fmt(sem, "%.1f") : ""),
                      Fmt(row.value("cost", nlohmann::json()), "%.3g"),
                      row.value("within_noise", false) ? "yes" : "no",
                      row.value("agrees", false) ? "yes" : "no", row.value("termination", "")});
  }
  return t;
}

// The table of a search that calibrated the aspect ratio per count (shape_search.h).
HtmlTable AspectRatioTable(const std::string& species, const nlohmann::json& rows) {
  HtmlTable t{.caption = species + ": clump sphere count and calibrated aspect ratio against the "
                         "measured angle (the paper's Fig. 3)",
              .header = {"spheres", "aspect ratio a/c [-]", "angle demcal [deg]", "cost (Σ z²)",
                         "within noise", "heaps", "wall [s]", "termination", "note"}};
  for (const nlohmann::json& row : rows) {
    const nlohmann::json sigma = row.value("aspect_ratio_sigma", nlohmann::json());
    const nlohmann::json sem = row.value("angle_sem_deg", nlohmann::json());
    const bool sphere = row.value("count", 0) == 1;
    t.rows.push_back(
        {std::to_string(row.value("count", 0)),
         sphere ? "1 (sphere)"
                : Fmt(row.value("aspect_ratio", nlohmann::json()), "%.2f") +
                      (sigma.is_number() ? " ± " + Fmt(sigma, "%.2f") : "") +
                      (row.value("aspect_at_bound", false) ? " (at bound)" : "") +
                      (row.value("local_fit", false) ? " (line)" : ""),
         Fmt(row.value("angle_deg", nlohmann::json()), "%.1f") +
             (sem.is_number() ? " ± " + Fmt(sem, "%.1f") : ""),
         Fmt(row.value("cost", nlohmann::json()), "%.3g"),
         row.value("within_noise", false) ? "yes" : "no", std::to_string(row.value("heaps", 0)),
         Fmt(row.value("wall_time_s", nlohmann::json()), "%.0f"), row.value("termination", ""),
         row.value("note", "")});
  }
  return t;
}

}  // namespace

bool AddClumpCountTable(const std::string& species, const nlohmann::json& entry, HtmlReport* r,
                        std::string* error) {
  if (!entry.is_object() || !entry.contains("clump_table") || entry["clump_table"].empty())
    return true;
  const nlohmann::json& rows = entry["clump_table"];
  const HtmlTable t = rows[0].contains("aspect_ratio") ? AspectRatioTable(species, rows)
                                                      : CountTable(species, rows);
  if (!r->Table(t, error)) return false;
  if (entry.contains("clump_note") && entry["clump_note"].is_string())
    r->Paragraph(species + ": " + entry["clump_note"].get<std::string>() + ".");
  return true;
}

}  // namespace demcal::workflow
