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
#include <atomic>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <thread>

#include "objectives/common/replicates.h"
#include "experiments/common/run_experiment.h"
#include "experiments/common/experiment_file.h"
#include "experiments/segregation/segregation_result.h"
#include "files/json_document.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/segregation_metrics.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {
namespace {

namespace fs = std::filesystem;

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
  for (const auto& [name, s] : ctx.results["species"]["species"].items()) {
    if (s["value"].is_number())
      SetPairProperty(&base, name, name, s["property"].get<std::string>(),
                      s["value"].get<double>());
    if (s.value("clump_count_used", 0) > 0 && s.contains("semi_axes"))  // stage 1's grain
      SetSpeciesClump(&base, name, s["semi_axes"].get<std::vector<double>>(),
                      s["clump_count_used"].get<int>());
  }
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
bool RunReplicate(const ReproduceContext& ctx, const Scenario& s, int r, int threads, const std::string& dir,
                  nlohmann::json* metrics, std::string* error) {
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
  return true;
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
    fs::create_directories(dir, ec);
    if (!WriteJsonFile(dir + "/experiment.json", scenarios[s].experiment, error)) return false;
    for (int r = 0; r < replicates; ++r)
      if (!ctx.journal->Find("segregation/" + scenarios[s].name + "/r" + std::to_string(r)))
        jobs.push_back({s, r});
  }
  const int total = static_cast<int>(scenarios.size()) * replicates;
  *ctx.log << "reproduce: segregation: " << scenarios.size() << " scenarios x " << replicates
           << " replicates, " << total - static_cast<int>(jobs.size()) << " from the journal\n";
  std::atomic<size_t> next{0};
  std::atomic<int> done{0};
  std::mutex mutex;
  std::string first_error;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&](size_t end, int threads) {
    for (size_t j; (j = next++) < end;) {
      const Scenario& s = scenarios[jobs[j].scenario];
      const int r = jobs[j].replicate;
      const std::string dir = ctx.StageDir("segregation") + "/" + s.name + "/r" + std::to_string(r);
      nlohmann::json metrics;
      std::string why;
      bool ok = RunReplicate(ctx, s, r, threads, dir, &metrics, &why) &&
                ctx.journal->Record("segregation/" + s.name + "/r" + std::to_string(r), metrics, &why);
      std::lock_guard lock(mutex);
      if (!ok && first_error.empty()) first_error = why;
      const int n = ++done;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!ctx.quiet)
        *ctx.log << "reproduce: segregation run " << n << "/" << jobs.size() << " (" << s.name << " r"
                 << r << ") done; elapsed " << std::lround(elapsed) << " s, ETA "
                 << std::lround(elapsed / n * (jobs.size() - n)) << " s\n" << std::flush;
    }
  };
  // Heaps run one per core, single-threaded. When the heaps do not divide into full rounds, the
  // odd ones go first, sharing all cores as simulation threads (results do not depend on the
  // thread count): 3 heaps on 2 cores take one 2-thread heap and one 2-heap round, not two rounds
  // of which the second leaves a core idle.
  const int cores = std::max(1, ctx.threads > 0 ? ctx.threads : static_cast<int>(std::thread::hardware_concurrency()));
  const size_t odd = jobs.size() % cores;
  auto run_round = [&](size_t end, int workers, int threads) {
    std::vector<std::thread> pool;
    for (int i = 0; i < workers; ++i) pool.emplace_back(worker, end, threads);
    for (std::thread& t : pool) t.join();
  };
  if (odd > 0) {
    const int odd_jobs = static_cast<int>(odd);
    run_round(odd, odd_jobs, objectives::ThreadsPerReplicate(odd_jobs, cores));
  }
  next = odd;  // a worker that found the first round empty still took an index
  run_round(jobs.size(), std::min<int>(cores, static_cast<int>(jobs.size() - odd)), 1);
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
