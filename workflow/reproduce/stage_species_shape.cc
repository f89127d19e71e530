// Stage 1 for a species whose clump aspect ratio is calibrated (shape_search.h): the entry has
// the keys of the fixed-shape entry (stage_species.cc) that the later stages and the report read
// — property and value (the held one), measured, simulated, clump_count_used, semi_axes,
// calibrated_experiment — so they run the grain kept without knowing how it was found.
#include <cmath>

#include "core/math/number_text.h"
#include "files/json_document.h"
#include "objectives/farm/farm.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/shape_search.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {

bool RunShapeSpecies(const ReproduceContext& ctx, size_t k, nlohmann::json* species,
                     nlohmann::json* values, std::string* error) {
  const WorkflowSpecies& s = ctx.workflow->species[k];
  const std::string dir = ctx.StageDir("species") + "/" + s.name;
  ShapeSearch search;
  if (!RunShapeSearch(ctx, k, dir, &search, error)) return false;
  const nlohmann::json table = search.TableJson();
  const ShapeSearchRow* used = search.Used();
  nlohmann::json entry = {{"property", s.property},
                          {"value", s.start},
                          {"sigma", nullptr},
                          {"held", true},
                          {"clump_count", search.chosen},
                          {"aspect_ratio_bounds", {s.aspect_ratio.min, s.aspect_ratio.max}},
                          {"clump_table", table["rows"]},
                          {"clump_note", table["note"]},
                          {"clump_counts_not_run", search.not_run}};
  nlohmann::ordered_json experiment;
  if (!ReadExperimentJson(s.experiment_file, &experiment, error)) return false;
  SetPairProperty(&experiment, s.name, s.name, s.property, s.start);
  if (used) {
    const std::vector<double> semi_axes = {used->aspect_ratio, 1, 1};
    entry["clump_count_used"] = used->count;
    entry["semi_axes"] = semi_axes;
    entry["aspect_ratio"] = used->aspect_ratio;
    entry["aspect_ratio_sigma"] = NumOrNull(used->aspect_sigma);
    entry["measured"] = NumOrNull(used->measured_deg);
    entry["uncertainty"] = NumOrNull(used->uncertainty_deg);
    entry["simulated"] = NumOrNull(used->angle_deg);
    entry["sem"] = NumOrNull(used->angle_sem_deg);
    entry["termination"] = used->termination;
    entry["by_line"] = used->local_fit;
    entry["message"] = used->message;
    entry["result_dir"] = used->result_dir;
    SetSpeciesClump(&experiment, s.name, semi_axes, used->count);
  }
  const std::string calibrated = dir + "/calibrated_experiment.json";
  // Under mpirun only rank 0 writes; the others read it after the stage (run_reproduce.cc).
  if (objectives::farm::IsManager() && !WriteJsonFile(calibrated, experiment, error)) return false;
  entry["calibrated_experiment"] = calibrated;
  (*species)[s.name] = entry;

  const std::string held = s.property + " held at " + core::NumberText(s.start);
  const std::string note = search.chosen > 0
      ? "calibrated to it (clump count and aspect ratio; " + held + ")"
      : "not matched: " + search.note;
  const double angle = used ? used->angle_deg : NAN, sem = used ? used->angle_sem_deg : NAN;
  (*values)["angle_" + s.name + "_deg"] = ValueJson(angle, sem, note);
  (*values)["clump_count_" + s.name] =
      ValueJson(search.chosen > 0 ? search.chosen : NAN, NAN, search.note);
  (*values)["aspect_ratio_" + s.name] =
      ValueJson(used ? used->aspect_ratio : NAN, used ? used->aspect_sigma : NAN, search.note);
  return true;
}

}  // namespace demcal::workflow
