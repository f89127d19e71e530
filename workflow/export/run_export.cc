#include "workflow/export/run_export.h"

#include <filesystem>

#include "core/version.h"
#include "files/json_document.h"
#include "objectives/report/text_file.h"
#include "outputs/exit_codes.h"
#include "workflow/export/liggghts_number.h"

namespace demcal::workflow {
namespace {

bool FidelityOf(const ExperimentFile& file, const std::string& name, objectives::Fidelity* out,
                std::string* error) {
  if (name == "full") {
    *out = objectives::Fidelity{};
    out->rayleigh_fraction = file.fidelity.rayleigh_fraction;
  } else if (name == "file") {
    *out = file.fidelity;
  } else if (name == "quick") {
    *out = file.quick_fidelity;
  } else {
    *error = "--fidelity '" + name + "': allowed values are full, file, quick";
    return false;
  }
  return true;
}

nlohmann::ordered_json FidelityJson(const objectives::Fidelity& f) {
  return {{"name", f.name},
          {"size_scale", f.size_scale},
          {"stiffness_scale", f.stiffness_scale},
          {"rayleigh_fraction", f.rayleigh_fraction}};
}

}  // namespace

int RunExportLiggghts(const ExportOptions& options, std::ostream& log) {
  ExperimentFile file;
  std::string error;
  objectives::Fidelity fidelity;
  if (!LoadExperimentFile(options.experiment_path, &file, &error) ||
      !FidelityOf(file, options.fidelity, &fidelity, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  if (!options.params_path.empty()) {
    nlohmann::json params;
    if (!ReadJsonFile(options.params_path, "parameter file", &params, &error) ||
        !ApplyCalibratedParams(params, options.params_path, &file.model, &error)) {
      log << "error: " << error << "\n";
      return kExitInvalidInput;
    }
  }
  ExportRun run;
  std::string deck;
  std::vector<std::pair<std::string, std::string>> files;
  nlohmann::ordered_json summary;
  const std::vector<std::string> comments = {
      "experiment: " + file.source + " (" + file.experiment + ", seed " +
          std::to_string(file.seed) + ")",
      "parameters: " +
          (options.params_path.empty() ? "the experiment file's" : options.params_path),
      "fidelity: " + fidelity.name + " (size x" + Num(fidelity.size_scale) + ", stiffness x" +
          Num(fidelity.stiffness_scale) + ")"};
  if (!ExportRunOf(file, fidelity, &run, &error) ||
      !LiggghtsDeck(run, options, comments, &deck, &files, &summary, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir + "/post", ec);
  for (const auto& f : files)
    if (!ec && f.first.rfind("meshes/", 0) == 0)
      std::filesystem::create_directories(options.out_dir + "/meshes", ec);
  if (ec) {
    log << "error: cannot create '" << options.out_dir << "': " << ec.message() << "\n";
    return kExitOutputError;
  }
  nlohmann::ordered_json manifest{{"format", "demcal-liggghts-export/1"},
                                  {"demcal_version", kVersion},
                                  {"experiment", file.source},
                                  {"params", options.params_path},
                                  {"seed", file.seed},
                                  {"fidelity", FidelityJson(fidelity)}};
  manifest.update(summary);
  nlohmann::ordered_json written = {"in.demcal"};
  for (const auto& f : files) written.push_back(f.first);
  manifest["files"] = written;
  for (const auto& f : files) {
    if (!objectives::WriteTextFile(
            options.out_dir + "/" + f.first, [&](std::ostream& o) { o << f.second; }, &error)) {
      log << "error: " << error << "\n";
      return kExitOutputError;
    }
  }
  if (!objectives::WriteTextFile(
          options.out_dir + "/in.demcal", [&](std::ostream& o) { o << deck; }, &error) ||
      !WriteJsonFile(options.out_dir + "/export.json", manifest, &error)) {
    log << "error: " << error << "\n";
    return kExitOutputError;
  }
  log << "wrote " << options.out_dir << "/in.demcal (" << files.size() + 1
      << " deck files); run it there: liggghts -in in.demcal\n";
  return kExitOk;
}

}  // namespace demcal::workflow
