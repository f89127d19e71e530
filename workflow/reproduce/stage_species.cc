// Stage 1, species (paper section 2.4, Fig. 3): for each species of the workflow file, the pair
// property it names (the rolling friction by default) of the species with itself, calibrated so
// the poured heap matches the species' measured repose angle; with clump_counts, the smallest
// clump sphere count that matches (the calibration layer's clump loop), or, with an aspect_ratio,
// the smallest count whose calibrated aspect ratio matches (shape_search.h). The calibrated
// value is written into a copy of the species' experiment file
// (species/<name>/calibrated_experiment.json) for the stages after it.
#include <cmath>

#include "core/math/number_text.h"
#include "files/json_document.h"
#include "objectives/farm/farm.h"
#include "workflow/reproduce/calibration_steps.h"
#include "workflow/reproduce/clump_table.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/shape_search.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {

CalibrationStep SpeciesStep(const WorkflowFile& w, size_t k, const std::string& dir) {
  const WorkflowSpecies& s = w.species[k];
  return {.dir = dir + "/" + s.name,
          .experiment_file = s.experiment_file,
          .parameter = s.property + "_" + s.name,
          .property = s.property,
          .material_a = s.name,
          .material_b = s.name,
          .min = s.min, .max = s.max, .start = s.start,
          .table = w.measurements,
          .material = s.name,
          .conditions = {{"coating_PEG_wt_pct", 0}},
          .uncertainty = w.angle_uncertainty_deg,
          .uncertainty_note = w.angle_uncertainty_note,
          .replicates = w.replicates,
          // Held (the paper's Table 1 value): one candidate per count, at `start`.
          .max_evaluations = s.hold ? 1 : CalibrationStep{}.max_evaluations,
          // With a calibrated aspect ratio each count is a calibration of its own
          // (shape_search.h): this is the held-property study each starts from.
          .clump_counts = s.aspect_ratio.enabled ? std::vector<int>{} : s.clump_counts,
          .semi_axes = s.semi_axes};
}

bool RunSpeciesStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error) {
  const WorkflowFile& w = *ctx.workflow;
  nlohmann::json species = nlohmann::json::object(), values = nlohmann::json::object();
  std::vector<CalibrationStep> steps;  // the species do not wait on each other: run together
  std::vector<size_t> stepped;         // the species of each step
  for (size_t k = 0; k < w.species.size(); ++k) {
    const WorkflowSpecies& s = w.species[k];
    // A calibrated aspect ratio is a search over counts, each a calibration that waits on the
    // one before (shape_search.h): those species run on their own, before the others together.
    if (s.aspect_ratio.enabled) {
      *ctx.log << "reproduce: species " << k + 1 << "/" << w.species.size() << " " << s.name
               << ": clump count and aspect ratio, " << s.property << " held, against the "
               << "measured repose angle\n";
      if (!RunShapeSpecies(ctx, k, &species, &values, error)) return false;
      continue;
    }
    *ctx.log << "reproduce: species " << k + 1 << "/" << w.species.size() << " " << s.name
             << ": " << (s.hold ? "clump count, " + s.property + " held" : s.property)
             << " against the measured repose angle\n";
    steps.push_back(SpeciesStep(w, k, ctx.StageDir("species")));
    stepped.push_back(k);
  }
  std::vector<CalibrationOutcome> outcomes;
  if (!RunCalibrationSteps(ctx, steps, &outcomes, error)) return false;
  for (size_t i = 0; i < steps.size(); ++i) {
    const WorkflowSpecies& s = w.species[stepped[i]];
    const CalibrationStep& step = steps[i];
    const CalibrationOutcome& o = outcomes[i];
    nlohmann::json entry = o.ToJson();
    // The paper's Fig. 3, from the loop's own outputs. Without a matching count the later stages
    // run the nearest one (least cost), and the rows say it did not match.
    int used = o.clump_count;
    nlohmann::json used_row;
    if (!s.clump_counts.empty()) {
      // Only rank 0 wrote the loop's files under mpirun: every rank takes its table.
      std::string shared = objectives::farm::IsManager() ? ReadClumpCountTable(step.dir).dump()
                                                         : std::string();
      objectives::farm::Share(&shared);
      const nlohmann::json table = nlohmann::json::parse(shared);
      entry["semi_axes"] = s.semi_axes;
      entry["held"] = s.hold;
      entry["clump_table"] = table["rows"];
      entry["clump_note"] = table["note"];
      for (const nlohmann::json& row : table["rows"])
        if (row["count"] == o.clump_count) used_row = row;
      if (used <= 0 && !(used_row = NearestClumpRow(table["rows"])).is_null())
        used = used_row["count"].get<int>();
      entry["clump_count_used"] = used;
    }
    nlohmann::ordered_json experiment;
    if (!ReadExperimentJson(s.experiment_file, &experiment, error)) return false;
    if (std::isfinite(o.value)) SetPairProperty(&experiment, s.name, s.name, s.property, o.value);
    // The shape travels with the calibrated value: stages 3, 6 and 7 run that grain.
    if (used > 0) SetSpeciesClump(&experiment, s.name, s.semi_axes, used);
    const std::string calibrated = step.dir + "/calibrated_experiment.json";
    // Under mpirun only rank 0 writes; the others read the file after the
    // stage, once rank 0 has written it (StageEnd in run_reproduce.cc).
    if (objectives::farm::IsManager() && !WriteJsonFile(calibrated, experiment, error))
      return false;
    entry["property"] = s.property;
    entry["calibrated_experiment"] = calibrated;
    species[s.name] = entry;
    const std::string how = s.hold ? "clump count; " + s.property + " held" : s.property;
    std::string angle_note = o.Matched() ? "calibrated to it (" + how + ")" : o.MatchText();
    if (o.Matched() && o.by_line) angle_note += "; " + o.MatchText();
    double angle = o.simulated, angle_sem = o.sem;
    std::string count_note =
        s.clump_counts.empty() ? "shape fixed by the workflow file: " + w.shape_assumption : "";
    if (!s.clump_counts.empty() && o.clump_count <= 0 && used > 0) {
      const std::string held = s.property + " held at " + core::NumberText(s.start);
      angle = used_row["angle_deg"].is_number() ? used_row["angle_deg"].get<double>() : NAN;
      angle_sem = used_row["angle_sem_deg"].is_number() ? used_row["angle_sem_deg"].get<double>()
                                                        : NAN;
      count_note = "no count matched the measured angle within noise with " + held +
                   "; the nearest, " + std::to_string(used) + " spheres, is what the later "
                   "stages run (the shape rule's aspect ratio, not the friction, is what to "
                   "revisit)";
      angle_note = "not matched: the nearest clump count (" + std::to_string(used) +
                   " spheres) with " + held;
    }
    values["angle_" + s.name + "_deg"] = ValueJson(angle, angle_sem, angle_note);
    values["clump_count_" + s.name] =
        ValueJson(o.clump_count > 0 ? o.clump_count : NAN, NAN, count_note);
  }
  *result = {{"species", species}, {"values", values}};
  return true;
}

}  // namespace demcal::workflow
