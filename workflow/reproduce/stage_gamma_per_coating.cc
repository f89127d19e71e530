// Stage 3, Γ per coating level (paper section 2.5.2, Fig. 6): for each coating level of the
// workflow file, Γ of the coated pair (EP–EP) calibrated so the poured heap of the coated species
// (its experiment file as calibrated by stage 1) matches that level's repose angle, starting from
// 2γ carried to the simulation stiffness at constant Coh (stage 2). The bracket optimiser stops
// at the first Γ whose angle is within the noise of the measurement, so two Γ whose angles are
// closer than their noise are never told apart. Each level's row is read from the measurement
// table, or else from the synthetic table (then every output of the level says synthetic); a
// level with no row in either is skipped and listed with the reason (its summary rows say "not
// run"), so the curve is fitted to the levels that have data.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "files/measurement_table.h"
#include "workflow/reproduce/calibration_steps.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {
namespace {

std::string LevelName(double w) {
  char text[32];
  std::snprintf(text, sizeof(text), "w%g", w);
  return text;
}

}  // namespace

// A table that cannot be read (e.g. a synthetic recipe that produced no rows) counts as not
// having the row: the reason names the file.
void CoatingLevelTable(const WorkflowFile& w, double level, std::string* table, std::string* why) {
  const calibrate::Condition condition = {{w.coating.covariate, std::to_string(level)}};
  why->clear();
  for (const std::string& path : {w.measurements, w.synthetic_measurements}) {
    if (path.empty()) continue;
    MeasurementTable t;
    std::string problem;
    if (!LoadMeasurementTable(path, &t, &problem) ||
        !t.Find("angle_deg", w.coating.material, condition, &problem)) {
      *why += (why->empty() ? "" : "; ") + problem;
      continue;
    }
    *table = path;
    return;
  }
  table->clear();
}

CalibrationStep CoatingLevelStep(const WorkflowFile& w, double level, const std::string& table,
                                 const std::string& experiment, double start,
                                 const std::string& dir) {
  const WorkflowCoating& c = w.coating;
  return {.dir = dir + "/" + LevelName(level),
          .experiment_file = experiment,
          .parameter = "gamma_" + LevelName(level),
          .property = "interfacial_energy_J_m2",
          .material_a = c.material,
          .material_b = c.material,
          .min = c.gamma_min_J_m2, .max = c.gamma_max_J_m2, .start = start,
          .table = table,
          .material = c.material,
          .conditions = {{c.covariate, level}},
          .uncertainty = w.angle_uncertainty_deg,
          .uncertainty_note = w.angle_uncertainty_note,
          .replicates = w.replicates};
}

bool RunGammaPerCoatingStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error) {
  const WorkflowFile& w = *ctx.workflow;
  const WorkflowCoating& c = w.coating;
  const nlohmann::json& species = ctx.results["species"]["species"];
  const std::string experiment = species.contains(c.material)
                                     ? species[c.material]["calibrated_experiment"].get<std::string>()
                                     : c.experiment_file;
  const double start = std::clamp(ctx.results["cohesion"]["gamma_sim_J_m2"].get<double>(),
                                  c.gamma_min_J_m2, c.gamma_max_J_m2);
  nlohmann::json levels = nlohmann::json::array(), values = nlohmann::json::object();
  std::vector<CalibrationStep> steps;  // the levels with a row do not wait on each other
  std::vector<std::string> skipped(c.levels.size());  // why a level has no row
  for (size_t k = 0; k < c.levels.size(); ++k) {
    const double level = c.levels[k];
    std::string table, why;
    CoatingLevelTable(w, level, &table, &why);
    if (table.empty()) {
      *ctx.log << "reproduce: coating level " << level << " wt%: no angle row: " << why
               << "; skipped\n";
      skipped[k] = "no angle_deg row: " + why;
      continue;
    }
    *ctx.log << "reproduce: coating level " << k + 1 << "/" << c.levels.size() << ": Γ of "
             << c.material << "-" << c.material << " at " << level << " wt%\n";
    steps.push_back(CoatingLevelStep(w, level, table, experiment, start,
                                     ctx.StageDir("gamma_per_coating")));
  }
  std::vector<CalibrationOutcome> outcomes;
  if (!RunCalibrationSteps(ctx, steps, &outcomes, error)) return false;
  for (size_t k = 0, run = 0; k < c.levels.size(); ++k) {
    const double level = c.levels[k];
    char key[64];
    if (!skipped[k].empty()) {
      levels.push_back({{"wt_pct", level}, {"skipped", skipped[k]},
                        {"value", nullptr}, {"sigma", nullptr}, {"synthetic", false}});
      std::snprintf(key, sizeof(key), "gamma_w%g_J_m2", level);
      values[key] = ValueJson(NAN, NAN, "no angle at this level in the tables");
      continue;
    }
    const CalibrationOutcome& o = outcomes[run++];
    nlohmann::json entry = o.ToJson();
    entry["wt_pct"] = level;
    entry["synthetic"] = o.provenance == "synthetic";
    levels.push_back(entry);
    std::snprintf(key, sizeof(key), "gamma_w%g_J_m2", level);
    const bool synthetic = o.provenance == "synthetic";
    values[key] = ValueJson(o.value, o.sigma, o.MatchText(), synthetic);
    std::snprintf(key, sizeof(key), "angle_EP_w%g_deg", level);
    values[key] = ValueJson(o.simulated, o.sem,
                            o.by_line ? "the line's value at its crossing"
                                      : "the calibrated heap's angle",
                            synthetic);
  }
  *result = {{"start_gamma_J_m2", start}, {"levels", levels}, {"values", values}};
  return true;
}

}  // namespace demcal::workflow
