#include "workflow/calibration/run_study.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "workflow/files/aor_json.h"
#include "workflow/calibration/calibration_outputs.h"
#include "workflow/exit_codes.h"
#include "workflow/experiments/experiment_runner.h"
#include "workflow/experiments/experiment_setup.h"
#include "workflow/files/json_document.h"
#include "workflow/files/study_file.h"
#include "calibrate/aor_observable.h"
#include "calibrate/evaluation_journal.h"
#include "objectives/aor/aor_experiment.h"

namespace demcal::workflow {
namespace {

// What the journal's results depend on: the experiment file as read, the fidelity, the seed and
// which pair properties the parameters set (not bounds or budgets: records are keyed by value).
std::string Fingerprint(const StudyFile& study, const objectives::Fidelity& fidelity, uint64_t seed) {
  nlohmann::json experiment;
  std::string ignored;
  ReadJsonFile(study.experiment_path, "experiment file", &experiment, &ignored);
  std::ostringstream text;
  text << experiment.dump() << "|" << FidelityJson(fidelity).dump() << "|seed=" << seed;
  for (const calibrate::Parameter& p : study.space.parameters)
    text << "|" << calibrate::PairPropertyKey(p.property) << ":" << p.material_i << ":" << p.material_j;
  uint64_t hash = 1469598103934665603ull;  // FNV-1a, 64 bit
  for (unsigned char c : text.str()) hash = (hash ^ c) * 1099511628211ull;
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << hash;
  return hex.str();
}

std::string Duration(double s) {
  std::ostringstream out;
  if (s < 90) out << std::lround(s) << " s";
  else out << std::lround(s / 60) << " min";
  return out.str();
}

// One line per candidate: what was tried, what came out, and the time left at most.
calibrate::CalibrationProgress ProgressLine(const StudyFile& st, int budget, std::ostream& log) {
  return [&st, budget, &log](const calibrate::Evaluation& e, const calibrate::TrialResult& t, double elapsed) {
    std::ostringstream line;
    line.precision(4);
    line << "calibrate: candidate " << e.index + 1 << "/" << budget << "  " << st.space.Describe(e.parameters)
         << " -> ";
    if (t.ok) line << st.measurement.observable << " " << e.summary.mean << " +- " << e.summary.sem;
    else line << "no value (" << e.status << ")";
    line << " (measured " << st.measurement.value << " +- " << st.measurement.uncertainty << ")";
    if (e.reused) line << " [" << e.reused << " from journal]";
    const double per = elapsed / (e.index + 1);
    line << "  elapsed " << Duration(elapsed) << ", ETA <= " << Duration(per * (budget - e.index - 1));
    log << line.str() << "\n" << std::flush;
  };
}

}  // namespace

int RunCalibrate(const CalibrateOptions& options, std::ostream& log) {
  StudyFile study;
  std::string error;
  if (!LoadStudyFile(options.study_path, &study, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  const ExperimentFile& file = study.experiment;
  const objectives::Fidelity fidelity = options.quick ? file.quick_fidelity : file.fidelity;
  if (!fidelity.IsValid(&error)) {
    log << "error: " << file.source << ": " << error << "\n";
    return kExitInvalidInput;
  }
  // The aor section checked against the model at this fidelity, and one run's scene built and
  // validated before anything runs (as `demcal experiment aor` does).
  ExperimentContext context;
  context.fidelity = fidelity;
  PreparedExperiment<objectives::AorSettings> prepared;
  auto build = [](const core::Scene& model, const objectives::AorSettings& settings, uint64_t seed) {
    int64_t fixed = 0;
    return objectives::BuildAorScene(model, settings, seed, &fixed);
  };
  if (!PrepareExperiment(file, context, ParseAorSection, build, &prepared, log)) return kExitInvalidInput;
  if (options.max_evaluations > 0) study.options.optimiser_options.max_evaluations = options.max_evaluations;
  const uint64_t seed = study.has_seed ? study.seed : file.seed;
  const int replicates = study.replicates > 0 ? study.replicates : file.replicates;
  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec) {
    log << "error: --out: cannot create '" << options.out_dir << "': " << ec.message() << "\n";
    return kExitOutputError;
  }
  calibrate::EvaluationJournal journal;
  if (!journal.Open(options.out_dir + "/journal.jsonl", Fingerprint(study, fidelity, seed), &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  if (!options.quiet && journal.LoadedRecords() > 0)
    log << "calibrate: resuming: " << journal.LoadedRecords() << " replicate runs in " << journal.path() << "\n";
  const calibrate::AorObservable observable(prepared.settings);
  calibrate::EvaluatorOptions eo{.replicates = replicates, .seed = seed, .workers = options.threads};
  eo.prepare = [fidelity](core::Scene* model) { objectives::ApplyFidelity(fidelity, model); };
  calibrate::ReplicatedEvaluator evaluator(file.model, study.space, observable, eo, &journal);
  const auto start = std::chrono::steady_clock::now();
  const int budget = study.options.optimiser_options.max_evaluations;
  const calibrate::CalibrationSummary summary =
      calibrate::Calibrate(evaluator, study.space, study.measurement, study.options,
                           options.quiet ? calibrate::CalibrationProgress{} : ProgressLine(study, budget, log));
  if (summary.termination == "invalid") {
    log << "error: " << study.source << ": " << summary.message << "\n";
    return kExitInvalidInput;
  }
  CalibrationRunInfo info{&study, fidelity, replicates, seed,
                          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  if (!options.quiet) log << summary.BriefReport(study.space, study.measurement);
  if (!WriteCalibrationOutputs(options.out_dir, info, summary, &error)) {
    log << "error: " << error << "\n";
    return kExitOutputError;
  }
  if (!summary.journal_error.empty()) log << "warning: " << summary.journal_error << "\n";
  return summary.ok() ? kExitOk : kExitRunFailed;
}

}  // namespace demcal::workflow
