// Stage 7, fidelity check: the coated species' heap at the check level (0.5 wt%) with its
// calibrated Γ, re-run at a finer fidelity (smaller coarse-graining, stiffer). If the Cohesion-
// number scaling (objectives/common/fidelity.h) carries Γ correctly between fidelities, the angle
// does not move beyond its noise. Default run: the workflow's fidelity_check size and stiffness
// scales against the experiment's calibration fidelity; with --quick: the experiment's
// calibration fidelity against its quick one (a cheaper step of the same ladder).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>

#include "experiments/common/run_experiment.h"
#include "experiments/common/experiment_file.h"
#include "files/json_document.h"
#include "objectives/farm/farm.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {

bool RunFidelityCheckStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error) {
  const WorkflowFidelityCheck& fc = ctx.workflow->fidelity_check;
  const WorkflowCoating& c = ctx.workflow->coating;
  nlohmann::json level;
  for (const nlohmann::json& l : ctx.results["gamma_per_coating"]["levels"])
    if (l["wt_pct"].get<double>() == fc.wt_pct) level = l;
  if (!fc.enabled || level.is_null() || !level["value"].is_number()) {
    const char* why = !fc.enabled ? "disabled in the workflow file"
                                  : "no calibrated Γ at the check level";
    *result = {{"enabled", false}, {"why", why},
               {"values", {{"fidelity_angle_shift_deg", ValueJson(NAN, NAN, why)}}}};
    return true;
  }
  const nlohmann::json& species = ctx.results["species"]["species"];
  const std::string source = species.contains(c.material)
      ? species[c.material]["calibrated_experiment"].get<std::string>() : c.experiment_file;
  nlohmann::ordered_json file;
  if (!ReadExperimentJson(source, &file, error)) return false;
  SetPairProperty(&file, c.material, c.material, "interfacial_energy_J_m2", level["value"].get<double>());
  nlohmann::ordered_json fine = ctx.quick
      ? file["fidelity"]
      : nlohmann::ordered_json{{"name", "fidelity_check"}, {"size_scale", fc.size_scale},
                               {"stiffness_scale", fc.stiffness_scale}};
  file["fidelity"] = fine;
  file["replicates"] = fc.replicates;
  const std::string dir = ctx.StageDir("fidelity_check");
  const std::string path = dir + "/experiment.json";
  const bool writer = objectives::farm::IsManager();  // under mpirun only rank 0 writes
  if (writer) std::filesystem::create_directories(dir);
  ExperimentFile experiment;
  if ((writer && !WriteJsonFile(path, file, error)) ||
      !ParseEditedExperiment(file, path, &experiment, error))
    return false;
  if (experiment.experiment != "aor")
    return *error = path + ": field 'experiment' = '" + experiment.experiment +
                    "' but the fidelity check runs 'aor'", false;
  *ctx.log << "reproduce: fidelity check: " << c.material << " at " << fc.wt_pct << " wt%, size x"
           << fine["size_scale"] << ", stiffness x" << fine["stiffness_scale"] << "\n";
  ExperimentContext context = ExperimentContextFor(experiment, dir, /*quick=*/false);
  context.replicates = fc.replicates;
  context.quiet = ctx.quiet;
  // The experiment is one run of the farm (under mpirun one rank runs its replicates, with
  // --threads cores, and writes its folder); its outcome travels as {code, n, mean, sem, log}.
  nlohmann::json outcome;
  objectives::farm::Job job;
  job.count = 1;
  job.fingerprint = std::hash<std::string>{}(file.dump());
  job.run = [&](int) {
    context.threads = objectives::farm::Farmed() && ctx.threads == 0 ? 1 : ctx.threads;
    const double start_unix_s = objectives::farm::UnixNow();
    std::ostringstream log;
    const ExperimentResult run = RunExperimentFile(experiment, context, ctx.quiet ? log : *ctx.log);
    const objectives::Summary* angle = run.Value("angle_deg");
    const objectives::Summary none;
    const objectives::Summary& a = angle ? *angle : none;
    const bool ran = angle && (run.status == ExperimentStatus::kOk ||
                               run.status == ExperimentStatus::kRunFailed);
    outcome = {{"code", ExitCodeOf(run.status)}, {"ran", ran}, {"log", log.str()},
               {"mean", a.n > 0 ? nlohmann::json(a.mean) : nlohmann::json()},
               {"sem", a.n > 1 ? nlohmann::json(a.sem) : nlohmann::json()},
               {"run", {{"host", objectives::farm::HostName()},
                        {"rank", objectives::farm::Rank()},
                        {"start_unix_s", start_unix_s},
                        {"end_unix_s", std::max(start_unix_s, objectives::farm::UnixNow())},
                        {"batch_unix_s", start_unix_s}}}};
  };
  job.save = [&](int) { return outcome.dump(); };
  job.load = [&](int, const std::string& bytes) { outcome = nlohmann::json::parse(bytes); };
  // Not copied to a second rank when slow: the copy would lock and write the same folder.
  objectives::farm::RunBatch(
      job, {.threads = 1, .run_time_limit_s = std::numeric_limits<double>::infinity()});
  const int code = outcome["code"].get<int>();
  if (!outcome["ran"].get<bool>()) {
    *error = "fidelity check in '" + dir + "' ended with exit code " + std::to_string(code);
    if (ctx.quiet) *error += ": " + outcome["log"].get<std::string>();
    return false;
  }
  const double fine_angle = outcome["mean"].is_number() ? outcome["mean"].get<double>() : NAN;
  const double fine_sem = outcome["sem"].is_number() ? outcome["sem"].get<double>() : NAN;
  const double base = level["simulated"].is_number() ? level["simulated"].get<double>() : NAN;
  const double base_sem = level["sem"].is_number() ? level["sem"].get<double>() : NAN;
  const double shift = fine_angle - base;
  const double sem = std::hypot(std::isfinite(fine_sem) ? fine_sem : 0,
                                std::isfinite(base_sem) ? base_sem : 0);
  char note[200];
  std::snprintf(note, sizeof(note), "%.1f ± %.1f° (finer) − %.1f ± %.1f° (calibration fidelity)",
                fine_angle, fine_sem, base, base_sem);
  *result = {{"enabled", true}, {"exit_code", code}, {"fine_fidelity", fine},
             {"fine_angle_deg", std::isfinite(fine_angle) ? nlohmann::json(fine_angle) : nlohmann::json()},
             {"fine_sem_deg", std::isfinite(fine_sem) ? nlohmann::json(fine_sem) : nlohmann::json()},
             {"base_angle_deg", NumOrNull(base)},
             {"base_sem_deg", std::isfinite(base_sem) ? nlohmann::json(base_sem) : nlohmann::json()},
             {"gamma_J_m2", level["value"]}, {"run", outcome["run"]},
             {"values", {{"fidelity_angle_shift_deg",
                          ValueJson(shift, sem > 0 ? sem : NAN, note, level.value("synthetic", false))}}}};
  return true;
}

}  // namespace demcal::workflow
