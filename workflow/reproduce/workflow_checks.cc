#include "workflow/reproduce/workflow_checks.h"

#include <algorithm>
#include <cmath>

#include "calibrate/cohesion_scaling.h"
#include "calibrate/condition.h"
#include "experiments/common/experiment_file.h"
#include "files/json_fields.h"
#include "files/measurement_table.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {
namespace {

std::string Field(const std::string& path) { return "field '" + path + "' "; }

// The first two entries that are the same (by `same`), as indices; {-1, -1} when none.
template <class T, class Same>
std::pair<int, int> Repeat(const std::vector<T>& items, Same same) {
  for (size_t j = 1; j < items.size(); ++j)
    for (size_t i = 0; i < j; ++i)
      if (same(items[i], items[j])) return {static_cast<int>(i), static_cast<int>(j)};
  return {-1, -1};
}

bool CheckRepeats(const WorkflowFile& w, std::string* error) {
  std::vector<std::string> names, keys;
  for (const WorkflowSpecies& s : w.species) names.push_back(s.name);
  for (const ReferenceValue& r : w.reference) keys.push_back(r.key);
  auto equal = [](const std::string& a, const std::string& b) { return a == b; };
  if (auto [i, j] = Repeat(names, equal); j >= 0)
    return *error = Field(IndexPath("species", j) + ".name") + "'" + names[j] + "' is the " +
                    "species of " + IndexPath("species", i) + " too; list each species once",
           false;
  auto same_level = [](double a, double b) {
    return calibrate::SameConditionCell(FormatNumber(a), FormatNumber(b));
  };
  if (auto [i, j] = Repeat(w.coating.levels, same_level); j >= 0)
    return *error = Field(IndexPath("coating.levels_wt_pct", j)) + "= " +
                    FormatNumber(w.coating.levels[j]) + " repeats " +
                    IndexPath("levels_wt_pct", i) + "; list each level once", false;
  if (auto [i, j] = Repeat(keys, equal); j >= 0)
    return *error = Field(IndexPath("reference", j) + ".key") + "'" + keys[j] + "' is the key " +
                    "of " + IndexPath("reference", i) + " too; each reference value once", false;
  return true;
}

// The synthetic table holds what demcal made, marked so in every output: a row claiming to be
// measured there would be reported as synthetic.
bool CheckSyntheticTable(const WorkflowFile& w, std::string* error) {
  if (w.synthetic_measurements.empty()) return true;
  MeasurementTable table;
  std::string ignored;  // unreadable: stage 3 treats it as holding no rows, and says so
  if (!LoadMeasurementTable(w.synthetic_measurements, &table, &ignored)) return true;
  for (const MeasurementRow& row : table.rows)
    if (row.provenance != "synthetic")
      return *error = Field("synthetic_measurements") + "'" + w.synthetic_measurements +
                      "' line " + std::to_string(row.line) + " has provenance '" +
                      row.provenance + "'; this table holds only rows demcal made (synthetic); " +
                      "put measured rows into 'measurements'", false;
  return true;
}

// `material` among the materials of the experiment file at `path`.
bool CheckMaterial(const std::string& field, const std::string& material,
                   const std::string& path, std::string* error) {
  ExperimentFile file;
  if (!LoadExperimentFile(path, &file, error)) return false;
  std::string names;
  for (const core::Material& m : file.model.materials) {
    if (m.name == material) return true;
    names += (names.empty() ? "" : ", ") + m.name;
  }
  return *error = Field(field) + "'" + material + "' is not a material of " + path +
                  " (its materials: " + names + ")", false;
}

bool CheckMaterials(const WorkflowFile& w, std::string* error) {
  const WorkflowCoating& c = w.coating;
  if (!CheckMaterial("coating.material", c.material, c.experiment_file, error)) return false;
  if (!w.segregation.enabled) return true;
  if (!CheckMaterial("coating.material", c.material, w.segregation.experiment_file, error))
    return false;
  for (size_t k = 0; k < c.partners.size(); ++k)
    if (!CheckMaterial(IndexPath("coating.partners", k), c.partners[k],
                       w.segregation.experiment_file, error))
      return false;
  return true;
}

// The calibrations stages 1 and 3 will run, parsed now: what they would refuse is refused
// before any stage runs, naming the workflow's field rather than the study written from it.
bool CheckCalibrations(const WorkflowFile& w, std::string* error) {
  std::string why;
  for (size_t k = 0; k < w.species.size(); ++k)
    if (!CheckCalibrationStep(SpeciesStep(w, k, "species"), &why))
      return *error = Field(IndexPath("species", k)) + "('" + w.species[k].name + "'): its " +
                      "calibration would be refused: " + why, false;
  const WorkflowCoating& c = w.coating;
  std::string experiment = c.experiment_file;  // stage 3 runs the coated species' calibrated copy
  for (const WorkflowSpecies& s : w.species)
    if (s.name == c.material) experiment = s.experiment_file;
  const double start = std::clamp(calibrate::EvaluateCohesion(w.cohesion).gamma_sim_J_m2,
                                  c.gamma_min_J_m2, c.gamma_max_J_m2);
  for (size_t k = 0; k < c.levels.size(); ++k) {
    std::string table;
    CoatingLevelTable(w, c.levels[k], &table, &why);
    if (table.empty()) continue;  // a level without an angle row is skipped, and reported
    if (!CheckCalibrationStep(CoatingLevelStep(w, c.levels[k], table, experiment,
                                               std::isfinite(start) ? start : c.gamma_min_J_m2,
                                               "gamma_per_coating"),
                              &why))
      return *error = Field(IndexPath("coating.levels_wt_pct", k)) + "(" +
                      FormatNumber(c.levels[k]) + " wt%): its calibration would be refused: " +
                      why, false;
  }
  return true;
}

}  // namespace

bool CheckWorkflowWhole(const WorkflowFile& w, std::string* error) {
  std::string why;
  const bool ok = CheckRepeats(w, &why) && CheckSyntheticTable(w, &why) &&
                  CheckMaterials(w, &why) && CheckCalibrations(w, &why);
  if (!ok) *error = w.source + ": " + why;
  return ok;
}

}  // namespace demcal::workflow
