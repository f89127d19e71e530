#include "workflow/calibration/run_study.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "calibrate/evaluation_journal.h"
#include "calibrate/parameter_covariance.h"
#include "calibrate/response_surface.h"
#include "core/math/fnv1a.h"
#include "objectives/farm/farm.h"
#include "workflow/calibration/calibration_outputs.h"
#include "workflow/calibration/clump_count_table.h"
#include "workflow/calibration/study_runs.h"
#include "outputs/exit_codes.h"
#include "outputs/output_lock.h"

namespace demcal::workflow {
namespace {

std::string Duration(double s) {
  std::ostringstream out;
  if (s < 90) out << std::lround(s) << " s";
  else out << std::lround(s / 60) << " min";
  return out.str();
}

// The driver sees the study's targets; the candidate targets' values (read from the same runs,
// or from runs of their own) are kept aside for "which measurement would help".
class StudyEvaluator final : public calibrate::CandidateEvaluator {
 public:
  StudyEvaluator(calibrate::TargetEvaluator* inner, size_t targets) : inner_(inner), targets_(targets) {}
  std::vector<calibrate::CandidateResult> EvaluateBatch(const std::vector<std::vector<double>>& p) override {
    std::vector<calibrate::CandidateResult> results = inner_->EvaluateBatch(p);
    for (calibrate::CandidateResult& r : results) Split(&r, &extra_.emplace_back());
    return results;
  }
  std::optional<calibrate::CandidateResult> AddReplicates(const std::vector<double>& p, int replicates) override {
    std::optional<calibrate::CandidateResult> r = inner_->AddReplicates(p, replicates);
    // extra_ runs parallel to the inner evaluator's history: one entry per candidate asked.
    const std::vector<calibrate::CandidateRuns>& asked = inner_->history();
    size_t k = asked.size();
    while (k > 0 && asked[k - 1].parameters != p) --k;  // the last candidate with these parameters
    if (r && k > 0) Split(&*r, &extra_[k - 1]);
    return r;
  }
  const std::vector<std::vector<calibrate::TargetValue>>& extra() const { return extra_; }

 private:
  // The candidate targets' values go to `extra`; a failure of those only is not the candidate's.
  void Split(calibrate::CandidateResult* r, std::vector<calibrate::TargetValue>* extra) const {
    extra->assign(r->targets.begin() + targets_, r->targets.end());
    r->targets.resize(targets_);
    if (r->status != "ok" && !calibrate::IsInfeasibleStatus(r->status)) {
      r->status = "ok";
      for (const calibrate::TargetValue& t : r->targets)
        if (!t.ok()) r->status = t.status;
    }
  }

  calibrate::TargetEvaluator* inner_;
  size_t targets_;
  std::vector<std::vector<calibrate::TargetValue>> extra_;  // per candidate asked, in order
};

// One line per candidate: what was tried, what came out per target, and the time left at most.
calibrate::CandidateProgress ProgressLine(const StudyFile& st, int budget, std::ostream& log) {
  return [&st, budget, &log](const calibrate::Candidate& c, double elapsed) {
    std::ostringstream line;
    line.precision(4);
    line << "calibrate: candidate " << c.index + 1 << "/" << budget << "  " << st.space.Describe(c.parameters) << " ->";
    for (size_t k = 0; k < st.targets.size() && k < c.result.targets.size(); ++k) {
      const calibrate::TargetValue& v = c.result.targets[k];
      line << (k ? ";" : "") << " " << st.targets[k].target.name << " ";
      if (v.ok()) line << v.mean << " +- " << v.sem;
      else line << "no value (" << v.status << ")";
      line << " (measured " << st.targets[k].target.value << ")";
    }
    if (c.result.replicates_reused) line << " [" << c.result.replicates_reused << " from journal]";
    line << "  elapsed " << Duration(elapsed) << ", ETA <= " << Duration(elapsed / (c.index + 1) * (budget - c.index - 1));
    log << line.str() << "\n" << std::flush;
  };
}

// Sensitivities of the candidate targets at the best candidate, from their values at the
// evaluated candidates (the same response surface as the fitted targets).
std::vector<calibrate::TargetGain> CandidateGains(const StudyFile& st, const calibrate::CalibrationSummary& s,
                                                  const StudyEvaluator& evaluator) {
  std::vector<calibrate::TargetGain> gains;
  if (st.candidate_targets.empty() || s.best < 0 || s.jacobian.size() == 0) return gains;
  const std::vector<double> centre = s.candidates[s.best].unit;
  std::vector<calibrate::CandidateTarget> rows;
  for (size_t k = 0; k < st.candidate_targets.size(); ++k) {
    std::vector<calibrate::Sample> samples;
    const double u = st.candidate_targets[k].uncertainty;
    for (size_t c = 0; c < s.candidates.size() && c < evaluator.extra().size(); ++c) {
      const calibrate::TargetValue& v = evaluator.extra()[c][k];
      if (v.ok()) samples.push_back({s.candidates[c].unit, {true, {v.mean / u}, {v.sem / u}}});
    }
    const calibrate::ResponseSurface surface = calibrate::FitResponseSurface(samples, centre);
    if (!surface.ok) continue;
    rows.push_back({st.candidate_targets[k].name, std::vector<double>(surface.jacobian.cols())});
    for (Eigen::Index p = 0; p < surface.jacobian.cols(); ++p) rows.back().sensitivity[p] = surface.jacobian(0, p);
  }
  std::vector<std::string> names;
  for (const calibrate::Parameter& p : st.space.parameters) names.push_back(p.name);
  return calibrate::RankCandidateTargets(s.jacobian, rows, names, calibrate::SiPerUnit(st.space, centre));
}

struct Outcome {
  CalibrationResult result;
  double wall_per_run_s = 0;  // mean wall time of the replicate runs made now (cost per heap)
};

Outcome Failed(CalibrationStatus status, const calibrate::CalibrationSummary& summary = {}) {
  Outcome out;
  out.result.status = status;
  out.result.summary = summary;
  return out;
}

double WallPerRun(const calibrate::TargetEvaluator& evaluator) {
  double wall = 0;
  int runs = 0;
  for (const calibrate::CandidateRuns& c : evaluator.history())
    for (const auto& group : c.runs)
      for (const calibrate::ReplicateRecord& r : group)
        if (r.wall_time_s > 0) wall += r.wall_time_s, ++runs;
  return runs > 0 ? wall / runs : 0;
}

// One calibration of the study's continuous parameters into dir (with its own journal).
Outcome CalibrateInto(const StudyFile& st, const CalibrateSettings& o, int clumps,
                      const std::string& dir, std::ostream& log) {
  std::string error;
  StudyRuns runs;
  if (!BuildStudyRuns(st, o.quick, clumps, &runs, &error)) {
    log << "error: " << error << "\n";
    return Failed(CalibrationStatus::kInvalidInput);
  }
  namespace farm = objectives::farm;
  std::error_code ec;
  if (farm::IsManager()) std::filesystem::create_directories(dir, ec);
  if (ec) {
    log << "error: --out: cannot create '" << dir << "': " << ec.message() << "\n";
    return Failed(CalibrationStatus::kOutputError);
  }
  const uint64_t seed = st.has_seed ? st.seed : st.experiment().seed;
  calibrate::EvaluationJournal journal;
  journal.ExpectSeeds(seed);
  // The other ranks of a farm read the journal, never write it (rank 0 appends every result).
  if (!journal.Open(dir + "/journal.jsonl", runs.fingerprint, &error, st.space.Size(),
                    !farm::IsManager())) {
    log << "error: " << error << "\n";
    return Failed(journal.io_error() ? CalibrationStatus::kOutputError
                                     : CalibrationStatus::kInvalidInput);
  }
  {  // rank 0 appends only once every rank has read the same records
    core::Fnv1a64 loaded;
    loaded.Text(runs.fingerprint), loaded.Field(journal.LoadedRecords());
    farm::Rendezvous(loaded.digest());
  }
  if (!o.quiet && journal.LoadedRecords() > 0)
    log << "calibrate: resuming: " << journal.LoadedRecords() << " replicate runs in " << journal.path() << "\n";
  const int replicates = st.replicates > 0 ? st.replicates : st.experiment().replicates;
  calibrate::TargetEvaluator inner(st.space, runs.groups, runs.bindings,
                                   {.replicates = replicates,
                                    .seed = seed,
                                    .workers = o.threads,
                                    .run_time_limit_s = o.run_time_limit_s},
                                   &journal);
  StudyEvaluator evaluator(&inner, st.targets.size());
  calibrate::CalibrationOptions options = st.options;
  if (o.max_evaluations > 0) options.optimiser_options.max_evaluations = o.max_evaluations;
  std::vector<calibrate::Target> targets;
  for (const StudyTarget& t : st.targets) targets.push_back(t.target);
  const auto start = std::chrono::steady_clock::now();
  const int budget = options.optimiser_options.max_evaluations;
  const calibrate::CalibrationSummary summary = calibrate::Calibrate(
      evaluator, st.space, targets, options,
      o.quiet ? calibrate::CandidateProgress{} : ProgressLine(st, budget, log));
  if (!summary.journal_error.empty()) {  // nothing ran after it; what ran is journalled
    log << "error: " << summary.journal_error << "; the calibration stopped there: make room "
        << "and run the same command again to resume\n";
    return Failed(CalibrationStatus::kOutputError, summary);
  }
  if (summary.termination == calibrate::Termination::kInvalid) {
    log << "error: " << st.source << ": " << summary.message << "\n";
    return Failed(CalibrationStatus::kInvalidInput, summary);
  }
  CalibrationRunInfo info{&st, runs.fidelities.front(), replicates, seed,
                          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                          clumps, &inner, CandidateGains(st, summary, evaluator)};
  if (!o.quiet) log << summary.BriefReport(st.space);
  if (farm::IsManager() && !WriteCalibrationOutputs(dir, info, summary, &error)) {
    log << "error: " << error << "\n";
    return Failed(CalibrationStatus::kOutputError, summary);
  }
  Outcome out;
  out.result = CalibrationResultOf(st, summary);
  out.result.status = summary.ok() ? CalibrationStatus::kMatched : CalibrationStatus::kNotMatched;
  out.result.out_dir = dir;
  out.result.clump_count = clumps;
  out.wall_per_run_s = WallPerRun(inner);
  return out;
}

// The paper's section 2.4: calibrate at each clump count, then judge the table: the smallest
// count that matches is chosen, and the counts the data do not exclude are named as not told
// apart (JudgeClumpCounts). The result is the chosen count's (the largest count's when none
// matched) with the table.
CalibrationResult RunClumpCountLoop(const StudyFile& st, const CalibrateSettings& o,
                                    std::ostream& log) {
  std::vector<ClumpCountRow> rows;
  std::vector<CalibrationResult> per_count;
  for (int n : st.clump_count.counts) {
    if (!o.quiet) log << "calibrate: clump count " << n << " (" << st.clump_count.species << ")\n";
    Outcome r = CalibrateInto(st, o, n, o.out_dir + "/clumps_" + std::to_string(n), log);
    if (r.result.status == CalibrationStatus::kInvalidInput ||
        r.result.status == CalibrationStatus::kOutputError)
      return r.result;
    rows.push_back(ClumpCountRowOf(n, r.result.summary, r.wall_per_run_s));
    per_count.push_back(std::move(r.result));
  }
  const ClumpCountVerdict verdict = JudgeClumpCounts(rows);
  std::string error;
  if (objectives::farm::IsManager() && !WriteClumpCountOutputs(o.out_dir, st, rows, verdict, &error)) {
    log << "error: " << error << "\n";
    return Failed(CalibrationStatus::kOutputError).result;
  }
  if (!o.quiet) log << "calibrate: clump count: " << verdict.note << " (clump_count.csv)\n";
  size_t shown = per_count.size() - 1;
  for (size_t k = 0; k < per_count.size(); ++k)
    if (per_count[k].clump_count == verdict.chosen) shown = k;
  CalibrationResult result = std::move(per_count[shown]);
  result.status = verdict.chosen > 0 ? CalibrationStatus::kMatched : CalibrationStatus::kNotMatched;
  result.clump_count = verdict.chosen > 0 ? verdict.chosen : 0;
  result.clump_counts = std::move(rows);
  return result;
}

}  // namespace

CalibrationResult CalibrateStudy(const StudyFile& study, const CalibrateSettings& settings,
                                 std::ostream& log) {
  OutputLock lock;  // one process per output directory (this also creates it)
  std::string error;
  // Under mpirun the job is one process: rank 0 holds the lock (farm.h).
  if (objectives::farm::IsManager() && !LockOutputDirectory(settings.out_dir, "demcal calibrate " + study.source, &lock, &error)) {
    log << "error: --out: " << error << "\n";
    CalibrationResult refused;
    refused.status = CalibrationStatus::kOutputUnavailable;
    refused.message = "--out: " + error;
    return refused;
  }
  if (study.clump_count.enabled()) return RunClumpCountLoop(study, settings, log);
  return CalibrateInto(study, settings, 0, settings.out_dir, log).result;
}

int RunCalibrate(const CalibrateOptions& options, std::ostream& log) {
  StudyFile study;
  std::string error;
  if (!LoadStudyFile(options.study_path, &study, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  const CalibrateSettings settings{.out_dir = options.out_dir,
                                   .quick = options.quick,
                                   .max_evaluations = options.max_evaluations,
                                   .threads = options.threads,
                                   .quiet = options.quiet,
                                   .run_time_limit_s = options.run_time_limit_s};
  return ExitCodeOf(CalibrateStudy(study, settings, log).status);
}

}  // namespace demcal::workflow
