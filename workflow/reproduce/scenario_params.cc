#include "workflow/reproduce/scenario_params.h"

#include <filesystem>

#include "calibrate/liggghts_export.h"
#include "core/version.h"
#include "objectives/report/text_file.h"
#include "experiments/common/experiment_file.h"
#include "files/json_document.h"
#include "workflow/reproduce/experiment_edit.h"

namespace demcal::workflow {

bool WriteScenarioParams(const ReproduceContext& ctx, std::string* error) {
  const nlohmann::json& seg = ctx.results["segregation"];
  if (!seg.value("enabled", false)) return true;
  const std::string dir = ctx.out_dir + "/params";
  std::filesystem::create_directories(dir);
  for (const auto& [name, scenario] : seg["scenarios"].items()) {
    const std::string experiment_path = scenario["dir"].get<std::string>() + "/experiment.json";
    nlohmann::ordered_json experiment;
    ExperimentFile file;
    if (!ReadExperimentJson(experiment_path, &experiment, error) ||
        !LoadExperimentFile(experiment_path, &file, error))
      return false;
    const bool synthetic = scenario.value("synthetic", false);
    nlohmann::ordered_json params{
        {"format", "demcal-params/1"},
        {"scenario", name},
        {"materials", experiment["materials"]},
        {"species", experiment["species"]},
        {"interactions", experiment["interactions"]},
        {"contact_model", experiment.value("contact_model", nlohmann::ordered_json::object())},
        {"provenance",
         {{"workflow", ctx.workflow->source}, {"demcal_version", kVersion},
          {"fidelity", ctx.quick ? "quick" : "default"},
          {"synthetic", synthetic},
          {"note", "full-scale values (the experiment file's Young's moduli); Γ calibrated at the "
                   "stated fidelity and carried by the Cohesion number"}}}};
    const std::vector<std::string> comments{
        "demcal reproduce " + ctx.workflow->name + ", scenario " + name,
        std::string("fidelity: ") + (ctx.quick ? "quick" : "default") +
            (synthetic ? "; built on SYNTHETIC coating angles" : "")};
    const std::string deck = calibrate::LiggghtsMaterialInclude(file.model, comments);
    if (!WriteJsonFile(dir + "/" + name + ".json", params, error) ||
        !objectives::WriteTextFile(dir + "/" + name + ".liggghts",
                                   [&](std::ostream& out) { out << deck; }, error))
      return false;
  }
  return true;
}

}  // namespace demcal::workflow
