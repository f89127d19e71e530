#include "workflow/reproduce/run_reproduce.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "objectives/farm/farm.h"
#include "outputs/exit_codes.h"
#include "files/json_document.h"
#include "outputs/output_lock.h"
#include "workflow/reproduce/reproduce_report.h"
#include "workflow/reproduce/scenario_params.h"
#include "workflow/reproduce/stages.h"
#include "workflow/reproduce/summary_table.h"
#include "workflow/reproduce/workflow_checks.h"

#ifndef DEMCAL_SOURCE_DIR
#define DEMCAL_SOURCE_DIR "."
#endif

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;
namespace farm = objectives::farm;

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

DemcalValues CollectValues(const nlohmann::json& results) {
  DemcalValues values;
  for (const auto& [stage, result] : results.items()) {
    if (!result.contains("values")) continue;
    for (const auto& [key, v] : result["values"].items()) {
      DemcalValue d;
      if (v["mean"].is_number()) d.mean = v["mean"].get<double>();
      if (v["sem"].is_number()) d.sem = v["sem"].get<double>();
      d.note = v.value("note", "");
      d.synthetic = v.value("synthetic", false);
      d.comparable = v.value("comparable", true);
      values[key] = d;
    }
  }
  return values;
}

// Under mpirun every rank runs every stage (SPMD, objectives/farm/farm.h) and only rank 0 writes.
// At a stage's end rank 0 waits until each rank has reached it with the same values (a rank that
// differs ends the job), and the others wait until rank 0 has written the stage's files, which
// the next stages read (a species' calibrated experiment file).
void StageEnd(const nlohmann::json& result) {
  farm::Rendezvous(std::hash<std::string>{}(result.value("values", nlohmann::json()).dump()));
  std::string none;
  farm::Share(&none);
}

// Runs (or reads back from the journal) every stage in order; false with *error.
bool RunStages(ReproduceContext& ctx, nlohmann::json* timings, std::string* error) {
  const bool writer = farm::IsManager();
  const auto& stages = ReproduceStages();
  for (size_t k = 0; k < stages.size(); ++k) {
    const Stage& stage = stages[k];
    if (const nlohmann::json* done = ctx.journal->Find(stage.name)) {
      ctx.results[stage.name] = (*done)["result"];
      (*timings)[stage.name] = (*done)["wall_time_s"];
      *ctx.log << "reproduce: stage " << k + 1 << "/" << stages.size() << " " << stage.name
               << ": from the journal\n";
      continue;
    }
    *ctx.log << "reproduce: stage " << k + 1 << "/" << stages.size() << " " << stage.name << ": "
             << stage.title << "\n" << std::flush;
    std::error_code ec;
    if (writer) fs::create_directories(ctx.StageDir(stage.name), ec);
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json result;
    if (!stage.run(ctx, &result, error)) return false;
    const double wall = Seconds(start);
    ctx.results[stage.name] = result;
    (*timings)[stage.name] = wall;
    if ((writer && !WriteJsonFile(ctx.StageDir(stage.name) + "/stage_result.json",
                                  nlohmann::ordered_json::parse(result.dump()), error)) ||
        !ctx.journal->Record(stage.name, {{"result", result}, {"wall_time_s", wall}}, error))
      return false;
    StageEnd(result);
    *ctx.log << "reproduce: stage " << k + 1 << "/" << stages.size() << " " << stage.name
             << " done in " << std::lround(wall) << " s\n" << std::flush;
  }
  return true;
}

}  // namespace

int RunReproduce(const ReproduceOptions& options, std::ostream& log) {
  const auto start = std::chrono::steady_clock::now();
  const std::string root = options.repo_root.empty() ? DEMCAL_SOURCE_DIR : options.repo_root;
  const std::string path = ResolveWorkflowName(options.workflow, root);
  WorkflowFile workflow;
  std::string error;
  if (!LoadWorkflowFile(path, &workflow, &error)) {
    log << "error: " << error << "\n";
    if (path == options.workflow && !fs::exists(path))
      log << "  (a bundled workflow name is a folder datasets/NAME/ with a workflow.json)\n";
    return kExitInvalidInput;
  }
  if (!CheckWorkflowWhole(workflow, &error)) {  // before any stage: nothing half done
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  const bool writer = farm::IsManager();  // rank 0 under mpirun; the only rank that writes
  std::error_code ec;
  if (writer) fs::create_directories(options.out_dir, ec);
  if (ec) {
    log << "error: cannot create '" << options.out_dir << "': " << ec.message() << "\n";
    return kExitOutputError;
  }
  OutputLock lock;  // a held --out is a usage error, as for every command (exit 2)
  const std::string holder = "demcal reproduce " + options.workflow;
  if (writer && !LockOutputDirectory(options.out_dir, holder, &lock, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  StageJournal journal;
  // A k-section bracket asks for other candidates: its finished work is another run's.
  const std::string fingerprint =
      workflow.fingerprint + (options.quick ? "/quick" : "/default") +
      (options.bracket_points > 1 ? "/bracket_points=" + std::to_string(options.bracket_points)
                                  : "");
  std::string opened;  // the workers read the journal once rank 0 has opened (or created) it
  if (writer && journal.Open(options.out_dir + "/stages.jsonl", fingerprint, &error)) opened = "1";
  farm::Share(&opened);
  if (opened.empty() ||
      (!writer && !journal.Open(options.out_dir + "/stages.jsonl", fingerprint, &error, true))) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  farm::Rendezvous(journal.size());  // every rank resumes from the same finished work
  farm::Share(&opened);              // and no worker starts before that check
  ReproduceContext ctx{.workflow = &workflow, .out_dir = options.out_dir, .quick = options.quick,
                       .threads = options.threads, .quiet = options.quiet,
                       .bracket_points = options.bracket_points,
                       .calibrations_in_sequence = options.calibrations_in_sequence, .log = &log,
                       .journal = &journal};
  log << "reproduce: " << workflow.name << " (" << path << ") into " << options.out_dir
      << (options.quick ? " at --quick fidelity" : " at the default fidelity") << "\n";
  nlohmann::json timings = nlohmann::json::object();
  if (!RunStages(ctx, &timings, &error)) {
    log << "error: " << error << "\n";
    return error.find("cannot write") != std::string::npos ? kExitOutputError : kExitInvalidInput;
  }
  const std::vector<SummaryRow> rows =
      BuildSummaryRows(workflow.reference, CollectValues(ctx.results));
  const std::string fidelity = options.quick ? "quick" : "default";
  nlohmann::ordered_json summary = SummaryJson(workflow.name, fidelity, rows);
  summary["stage_wall_time_s"] = nlohmann::ordered_json::parse(timings.dump());
  summary["total_wall_time_s_this_run"] = Seconds(start);
  ReportInputs report{.workflow = &workflow, .results = &ctx.results, .rows = &rows,
                      .timings = &timings, .quick = options.quick, .out_dir = options.out_dir};
  if (!writer) return kExitOk;  // the job's exit code is rank 0's (farm::Session::Finish)
  if (!WriteJsonFile(options.out_dir + "/summary.json", summary, &error) ||
      !WriteScenarioParams(ctx, &error) || !WriteReproduceReport(report, &error)) {
    log << "error: " << error << "\n";
    return kExitOutputError;
  }
  log << "reproduce: done in " << std::lround(Seconds(start)) << " s: " << options.out_dir
      << "/report.html, summary.json (" << rows.size() << " rows)\n";
  return kExitOk;
}

}  // namespace demcal::workflow
