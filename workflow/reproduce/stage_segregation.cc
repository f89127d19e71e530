// Stage 6, segregation of the calibrated set (paper sections 3.1–3.5): the ternary heap of the
// workflow's segregation experiment file with the species' calibrated frictions (stage 1), under
// three scenarios:
//   uncoated   Γ = 0 everywhere;
//   coated     Γ(coated_wt_pct) of the curve (stage 4) on the coated pair, the dissimilar pairs
//              of stage 5 on the coated–uncoated pairs;
//   excessive  excessive_gamma_J_m2 on every contact of the coated species (paper section 3.5).
// Each scenario runs its replicates as separate segregation experiments (RunExperimentFile;
// replicate r: the file's seed replaced by ReplicateSeed(seed, r), one replicate each) side by
// side, each journalled when it finishes, so a kill loses only the runs in flight. Means ± sem
// over the replicates of each scenario feed summary.json.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

#include "experiments/common/experiment_file.h"
#include "experiments/common/run_experiment.h"
#include "experiments/segregation/segregation_result.h"
#include "files/json_document.h"
#include "objectives/common/replicates.h"
#include "objectives/farm/farm.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/pair_overrides.h"
#include "workflow/reproduce/segregation_metrics.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;
constexpr double kNeverCopy = std::numeric_limits<double>::infinity();  // farm::Options

struct Scenario {
  std::string name;
  nlohmann::ordered_json experiment;
  bool synthetic = false;
};

bool BuildScenarios(const ReproduceContext& ctx, std::vector<Scenario>* out, std::string* error) {
  const WorkflowFile& w = *ctx.workflow;
  nlohmann::ordered_json base;
  if (!ReadExperimentJson(w.segregation.experiment_file, &base, error)) return false;
  if (w.segregation.size_scale > 0) {  // the workflow's own default fidelity
    nlohmann::ordered_json& fidelity = base["fidelity"];
    if (!fidelity.is_object()) fidelity = nlohmann::ordered_json::object();
    fidelity["name"] = "workflow";
    fidelity["size_scale"] = w.segregation.size_scale;
    fidelity["stiffness_scale"] = w.segregation.stiffness_scale;
  }
  if (w.segregation.funnel_effective_orifice_diameter_m > 0 &&  // the workflow's orifice rule
      !SetFunnelOrificeRule(&base, w.segregation.funnel_effective_orifice_diameter_m,
                            w.segregation.funnel_beverloo_k))
    return *error = w.source + ": segregation.funnel_orifice is given but '" +
                    w.segregation.experiment_file + "' pours without a funnel (\"funnel\": false)",
           false;
  for (const auto& [name, s] : ctx.results["species"]["species"].items()) {
    if (s["value"].is_number())
      SetPairProperty(&base, name, name, s["property"].get<std::string>(),
                      s["value"].get<double>());
    if (s.value("clump_count_used", 0) > 0 && s.contains("semi_axes"))  // stage 1's grain
      SetSpeciesClump(&base, name, s["semi_axes"].get<std::vector<double>>(),
                      s["clump_count_used"].get<int>());
  }
  if (!ApplyPairOverrides(w, &base, error)) return false;
  const std::string ep = w.coating.material;
  const nlohmann::json& pairs = ctx.results["dissimilar_pairs"];
  Scenario uncoated{"uncoated", base};
  Scenario coated{"coated", base, pairs.value("synthetic", false)};
  if (pairs["coated_gamma_J_m2"].is_number()) {
    SetPairProperty(&coated.experiment, ep, ep, "interfacial_energy_J_m2",
                    pairs["coated_gamma_J_m2"].get<double>());
    for (const nlohmann::json& p : pairs["pairs"])
      if (p["gamma_J_m2"].is_number())
        SetPairProperty(&coated.experiment, ep, p["materials"][1].get<std::string>(),
                        "interfacial_energy_J_m2", p["gamma_J_m2"].get<double>());
  }
  Scenario excessive{"excessive", base};
  const double g = w.segregation.excessive_gamma_J_m2;
  SetPairProperty(&excessive.experiment, ep, ep, "interfacial_energy_J_m2", g);
  for (const std::string& partner : w.coating.partners)
    SetPairProperty(&excessive.experiment, ep, partner, "interfacial_energy_J_m2", g);
  *out = {uncoated};
  if (pairs["coated_gamma_J_m2"].is_number()) out->push_back(coated);
  out->push_back(excessive);
  return true;
}

// One replicate: its own experiment file (seed replaced; written as the record) and output folder.
// Under mpirun the rank that runs it writes that folder (a run's own files; the folder must be
// on a file system every rank sees, as the inputs are); its metrics carry where and when it ran
// under "run" (host, rank, start_unix_s, end_unix_s, batch_unix_s) for `demcal journal-stats`.
bool RunReplicate(const ReproduceContext& ctx, const Scenario& s, int r, int threads, const std::string& dir,
                  double batch_unix_s, nlohmann::json* metrics, std::string* error) {
  const double start_unix_s = objectives::farm::UnixNow();
  nlohmann::ordered_json document = s.experiment;
  const uint64_t seed = objectives::ReplicateSeed(document.value("seed", uint64_t{1}), r);
  document["seed"] = seed;
  document["replicates"] = 1;
  std::error_code ec;
  fs::create_directories(dir, ec);
  const std::string path = dir + "/experiment.json";
  ExperimentFile file;
  if (!WriteJsonFile(path, document, error) || !ParseEditedExperiment(document, path, &file, error))
    return false;
  ExperimentContext context = ExperimentContextFor(file, dir, ctx.quick);
  context.replicates = 1;
  context.threads = threads;
  context.quiet = true;
  std::ostringstream log;
  const ExperimentResult result = RunExperimentFile(file, context, log);
  const SegregationResult* segregation = result.Detail<SegregationResult>();
  const int code = ExitCodeOf(result.status);
  if (!segregation || (result.status != ExperimentStatus::kOk &&
                       result.status != ExperimentStatus::kRunFailed)) {
    *error = "segregation run in '" + dir + "' ended with exit code " + std::to_string(code) +
             ": " + log.str();
    return false;
  }
  *metrics = ExtractSegregationMetrics(*segregation);
  (*metrics)["seed"] = seed;
  (*metrics)["exit_code"] = code;
  (*metrics)["size_scale"] = context.fidelity.size_scale;  // the mixture angle's note
  (*metrics)["run"] = {{"host", objectives::farm::HostName()},
                       {"rank", objectives::farm::Rank()},
                       {"start_unix_s", start_unix_s},
                       {"end_unix_s", std::max(start_unix_s, objectives::farm::UnixNow())},
                       {"batch_unix_s", batch_unix_s}};
  return true;
}

// Runs jobs 0..count−1 on this machine's cores, run(j, simulation threads). Heaps run one per
// core, single-threaded. When the heaps do not divide into full rounds, the odd ones go first,
// sharing all cores as simulation threads (results do not depend on the thread count): 3 heaps
// on 2 cores take one 2-thread heap and one 2-heap round, not two rounds of which the second
// leaves a core idle.
void RunLocally(size_t count, int threads, const std::function<void(size_t, int)>& run) {
  const int cores =
      std::max(1, threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()));
  const size_t odd = count % cores;
  std::atomic<size_t> next{0};
  auto run_round = [&](size_t end, int workers, int simulation_threads) {
    std::vector<std::thread> pool;
    for (int i = 0; i < workers; ++i)
      pool.emplace_back([&, end, simulation_threads] {
        for (size_t j; (j = next++) < end;) run(j, simulation_threads);
      });
    for (std::thread& t : pool) t.join();
  };
  if (odd > 0) {
    const int odd_jobs = static_cast<int>(odd);
    run_round(odd, odd_jobs, objectives::ThreadsPerReplicate(odd_jobs, cores));
  }
  next = odd;  // a worker that found the first round empty still took an index
  run_round(count, std::min<int>(cores, static_cast<int>(count - odd)), 1);
}

}  // namespace

bool RunSegregationStage(ReproduceContext& ctx, nlohmann::json* result, std::string* error) {
  const WorkflowSegregation& seg = ctx.workflow->segregation;
  if (!seg.enabled) {
    *result = {{"enabled", false}, {"values", nlohmann::json::object()}};
    return true;
  }
  std::vector<Scenario> scenarios;
  if (!BuildScenarios(ctx, &scenarios, error)) return false;
  const int replicates = ctx.quick ? seg.quick_replicates : seg.replicates;
  struct Job { size_t scenario; int replicate; };
  std::vector<Job> jobs;
  for (size_t s = 0; s < scenarios.size(); ++s) {
    const std::string dir = ctx.StageDir("segregation") + "/" + scenarios[s].name;
    std::error_code ec;
    if (objectives::farm::IsManager()) {  // under mpirun only rank 0 writes the stage's files
      fs::create_directories(dir, ec);
      if (!WriteJsonFile(dir + "/experiment.json", scenarios[s].experiment, error)) return false;
    }
    for (int r = 0; r < replicates; ++r)
      if (!ctx.journal->Find("segregation/" + scenarios[s].name + "/r" + std::to_string(r)))
        jobs.push_back({s, r});
  }
  const int total = static_cast<int>(scenarios.size()) * replicates;
  *ctx.log << "reproduce: segregation: " << scenarios.size() << " scenarios x " << replicates
           << " replicates, " << total - static_cast<int>(jobs.size()) << " from the journal\n";
  std::mutex mutex;
  std::string first_error;
  int done = 0;
  const auto start = std::chrono::steady_clock::now();
  const double batch_unix_s = objectives::farm::UnixNow();
  auto key = [&](size_t j) {
    const Job& task = jobs[j];
    return "segregation/" + scenarios[task.scenario].name + "/r" + std::to_string(task.replicate);
  };
  // Replicate j's metrics, or {"error": why}.
  auto run = [&](size_t j, int threads) {
    const Scenario& s = scenarios[jobs[j].scenario];
    const int r = jobs[j].replicate;
    const std::string dir = ctx.StageDir("segregation") + "/" + s.name + "/r" + std::to_string(r);
    nlohmann::json metrics;
    std::string why;
    if (!RunReplicate(ctx, s, r, threads, dir, batch_unix_s, &metrics, &why))
      metrics = {{"error", why}};
    return metrics;
  };
  auto finish = [&](size_t j, nlohmann::json metrics) {  // journals it, then the progress
    std::string why = metrics.value("error", "");
    // The batch's start on this rank's clock, as for calibrate's records (a worker that ran the
    // replicate stamped its own).
    if (metrics.contains("run")) metrics["run"]["batch_unix_s"] = batch_unix_s;
    if (why.empty()) ctx.journal->Record(key(j), metrics, &why);
    std::lock_guard lock(mutex);
    if (!why.empty() && first_error.empty()) first_error = why;
    const int n = ++done;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!ctx.quiet)
      *ctx.log << "reproduce: segregation run " << n << "/" << jobs.size() << " ("
               << scenarios[jobs[j].scenario].name << " r" << jobs[j].replicate
               << ") done; elapsed " << std::lround(elapsed) << " s, ETA "
               << std::lround(elapsed / n * (jobs.size() - n)) << " s\n" << std::flush;
  };
  if (objectives::farm::Farmed()) {
    // Every scenario's replicates in one batch over the ranks, each single-threaded (--threads:
    // runs side by side per rank); rank 0 journals each as it arrives. A slow run is not copied
    // to another rank: the copy would lock and write the same folder (each run still ends, on
    // its simulation's wall-time budget).
    std::vector<nlohmann::json> metrics(jobs.size());
    std::string tasks;
    for (size_t j = 0; j < jobs.size(); ++j)
      tasks += key(j) + "=" + scenarios[jobs[j].scenario].experiment.dump() + "\n";
    objectives::farm::Job job;
    job.count = static_cast<int>(jobs.size());
    job.fingerprint = std::hash<std::string>{}(tasks);
    job.run = [&](int t) { metrics[t] = run(t, 1); };
    job.save = [&](int t) { return metrics[t].dump(); };
    job.load = [&](int t, const std::string& bytes) { metrics[t] = nlohmann::json::parse(bytes); };
    job.done = [&](int t) { finish(t, metrics[t]); };
    objectives::farm::RunBatch(job, {.threads = ctx.threads, .run_time_limit_s = kNeverCopy});
  } else {
    RunLocally(jobs.size(), ctx.threads,
               [&](size_t j, int threads) { finish(j, run(j, threads)); });
  }
  if (!first_error.empty()) return *error = first_error, false;
  nlohmann::json per_scenario = nlohmann::json::object();
  for (const Scenario& s : scenarios) {
    std::vector<nlohmann::json> runs;
    for (int r = 0; r < replicates; ++r)
      runs.push_back(*ctx.journal->Find("segregation/" + s.name + "/r" + std::to_string(r)));
    per_scenario[s.name] = SummariseSegregationRuns(runs);
    per_scenario[s.name]["synthetic"] = s.synthetic;
    per_scenario[s.name]["dir"] = ctx.StageDir("segregation") + "/" + s.name;
  }
  *result = {{"enabled", true}, {"replicates", replicates}, {"scenarios", per_scenario},
             {"values", SegregationSummaryValues(per_scenario, ctx.workflow->coating.material)}};
  return true;
}

}  // namespace demcal::workflow
