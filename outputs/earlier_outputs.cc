#include "outputs/earlier_outputs.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;

// Every file demcal simulate / experiment / calibrate writes (README, "Output files").
constexpr const char* kNames[] = {
    "summary.json",      "scene.json",           "final_particles.csv", "final_clumps.csv",
    "checkpoint.bin",    "vtk",                  "result.json",         "runs.csv",
    "rejected.json",     "evaluations.csv",      "calibrated_params.json",
    "calibrated_params.liggghts",                "calibration.svg",     "discharge_mass.svg",
    "discharge_composition.svg",
};
// Per-replicate outputs: "heap_profile_r0.svg", "outflow_r2.csv", ...
constexpr const char* kPrefixes[] = {
    "heap_profile_r",      "outflow_r",          "composition_r", "granule_tracks",
    "segregation_bins",    "segregation_indices", "heap_front",   "cov_per_layer",
};

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

bool IsDemcalOutputName(const std::string& name) {
  for (const char* n : kNames)
    if (name == n) return true;
  for (const char* p : kPrefixes)
    if (StartsWith(name, p)) return true;
  return false;
}

bool SetAsideEarlierOutputs(const std::string& dir, const std::vector<std::string>& keep,
                            std::vector<std::string>* moved, std::string* error) {
  moved->clear();
  std::error_code ec;
  std::vector<fs::path> found;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!IsDemcalOutputName(name)) continue;
    std::error_code same_ec;
    if (std::any_of(keep.begin(), keep.end(), [&](const std::string& k) {
          return !k.empty() && fs::equivalent(e.path(), k, same_ec);
        }))
      continue;
    // An empty vtk/ (made by an earlier rejected run) is no earlier output.
    std::error_code empty_ec;
    if (e.is_directory(empty_ec) && fs::is_empty(e.path(), empty_ec)) continue;
    found.push_back(e.path());
  }
  if (ec) {
    if (error) *error = "cannot list '" + dir + "': " + ec.message();
    return false;
  }
  if (found.empty()) return true;
  std::sort(found.begin(), found.end());
  const fs::path target = fs::path(dir) / kPreviousRunDir;
  fs::remove_all(target, ec);
  fs::create_directory(target, ec);
  if (ec) {
    if (error) *error = "cannot create '" + target.string() + "': " + ec.message();
    return false;
  }
  for (const fs::path& p : found) {
    fs::rename(p, target / p.filename(), ec);
    if (ec) {
      if (error)
        *error = "cannot move '" + p.string() + "' into '" + target.string() + "': " + ec.message();
      return false;
    }
    moved->push_back(p.filename().string());
  }
  return true;
}

}  // namespace demcal::workflow
