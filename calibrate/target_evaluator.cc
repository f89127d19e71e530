#include "calibrate/target_evaluator.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>

#include "core/math/fnv1a.h"
#include "objectives/common/replicates.h"
#include "objectives/farm/farm.h"

namespace demcal::calibrate {

// One replicate of one group at one candidate still to run.
struct TargetEvaluator::Task {
  int candidate = 0, group = 0, replicate = 0;
};

namespace {

// What a run adds to its record, as bytes for the farm (farm.h): CBOR keeps every double's bits.
std::string SaveOutcome(const ReplicateRecord& r) {
  const nlohmann::json j{{"status", r.status}, {"values", r.values}, {"wall", r.wall_time_s},
                         {"host", r.host},     {"rank", r.rank},     {"start", r.start_unix_s},
                         {"end", r.end_unix_s}};
  const std::vector<uint8_t> bytes = nlohmann::json::to_cbor(j);
  return std::string(bytes.begin(), bytes.end());
}

void LoadOutcome(const std::string& bytes, ReplicateRecord* r) {
  const nlohmann::json j = nlohmann::json::from_cbor(bytes);
  r->status = j.at("status").get<std::string>();
  r->values = j.at("values").get<std::map<std::string, double>>();
  r->wall_time_s = j.at("wall").get<double>();
  r->host = j.at("host").get<std::string>();
  r->rank = j.at("rank").get<int>();
  r->start_unix_s = j.at("start").get<double>();
  r->end_unix_s = j.at("end").get<double>();
}

// The batch's runs, in order: every rank of a farm must derive the same.
uint64_t Fingerprint(const std::vector<ReplicateRecord*>& records) {
  core::Fnv1a64 h;
  for (const ReplicateRecord* r : records) {
    h.Text(r->group);
    for (double p : r->parameters) h.Field(p);
    h.Field(r->replicate), h.Field(r->seed);
  }
  return h.digest();
}

}  // namespace

TargetEvaluator::TargetEvaluator(const ParameterSpace& space, std::vector<RunGroup> groups,
                                 std::vector<TargetBinding> targets,
                                 TargetEvaluatorOptions options, EvaluationJournal* journal)
    : space_(space),
      groups_(std::move(groups)),
      targets_(std::move(targets)),
      options_(options),
      journal_(journal),
      pool_(targets_.size()) {}

std::vector<CandidateResult> TargetEvaluator::EvaluateBatch(
    const std::vector<std::vector<double>>& si_parameters) {
  std::vector<CandidateRuns> batch;
  std::vector<CandidateResult> results = Run(si_parameters, options_.replicates, true, &batch);
  for (CandidateRuns& runs : batch) history_.push_back(std::move(runs));
  return results;
}

// The earlier runs of the candidate leave the pool: with enough replicates of its own, its
// spread is its own (a candidate whose heaps scatter far more than the others' would otherwise
// inflate every other candidate's sem).
std::optional<CandidateResult> TargetEvaluator::AddReplicates(
    const std::vector<double>& si_parameters, int replicates) {
  size_t h = history_.size();
  while (h > 0 && history_[h - 1].parameters != si_parameters) --h;
  if (h == 0 || replicates < 1) return std::nullopt;
  CandidateRuns& earlier = history_[h - 1];
  if (earlier.pooled)
    for (size_t k = 0; k < targets_.size(); ++k) pool_[k].Remove(Sample(earlier, targets_[k]).values);
  std::vector<CandidateRuns> batch;
  std::vector<CandidateResult> results = Run({si_parameters}, replicates, false, &batch, &earlier);
  earlier = std::move(batch[0]);
  return results[0];
}

std::vector<CandidateResult> TargetEvaluator::Run(const std::vector<std::vector<double>>& si_parameters,
                                                  int replicates, bool pooled,
                                                  std::vector<CandidateRuns>* out_runs,
                                                  const CandidateRuns* prior) {
  const int n = static_cast<int>(si_parameters.size()), g = static_cast<int>(groups_.size());
  std::vector<CandidateRuns>& batch = *out_runs;
  batch.assign(n, CandidateRuns{});
  std::vector<std::string> infeasible(n);
  std::vector<core::Scene> models(static_cast<size_t>(n) * g);
  std::vector<Task> pending;
  std::vector<int> reused(n, 0);
  for (int c = 0; c < n; ++c) {
    const std::vector<double>& p = si_parameters[c];
    batch[c].parameters = p;
    batch[c].pooled = pooled;
    batch[c].runs.assign(g, std::vector<ReplicateRecord>(replicates));
    // Once a record could not be written, nothing more runs: work that cannot be resumed
    // would be lost (the caller stops the calibration on the journal error).
    if (!journal_failure_.empty()) infeasible[c] = "the journal cannot be written";
    if (!infeasible[c].empty() || !space_.Feasible(p, &infeasible[c])) continue;
    for (int k = 0; k < g && infeasible[c].empty(); ++k) {  // every group's model first
      core::Scene& model = models[static_cast<size_t>(c) * g + k];
      model = groups_[k].model;
      if (!groups_[k].space.Apply(p, groups_[k].condition, &model, &infeasible[c])) break;
      if (groups_[k].prepare) groups_[k].prepare(&model);
    }
    if (!infeasible[c].empty()) continue;
    for (int k = 0; k < g; ++k)
      for (int r = 0; r < replicates; ++r) {
        const uint64_t seed = objectives::ReplicateSeed(options_.seed, r);
        ReplicateRecord& record = batch[c].runs[k][r];
        // A run of this candidate before it was given more replicates is taken as it is and
        // was counted then (as run, or as reused); only what the journal adds counts as reused.
        if (prior && r < static_cast<int>(prior->runs[k].size())) {
          record = prior->runs[k][r];
        } else if (const ReplicateRecord* done =
                       journal_ ? journal_->Find(groups_[k].key, p, r, seed) : nullptr) {
          record = *done;
          ++reused[c];
        } else {
          record.parameters = p, record.replicate = r, record.seed = seed;
          record.group = groups_[k].key, record.status = "pending";
          pending.push_back({c, k, r});
        }
      }
  }
  std::mutex error_mutex;
  std::vector<std::string> journal_errors(n);
  std::vector<ReplicateRecord*> slots;
  for (const Task& task : pending)
    slots.push_back(&batch[task.candidate].runs[task.group][task.replicate]);
  objectives::farm::Job job;
  // The farm's batch start: shared by the calibrations run together (farm::RunGathered), so
  // journal-stats sees their runs as one batch.
  job.started = [&](double unix_s) {
    for (ReplicateRecord* slot : slots) slot->batch_unix_s = unix_s;
  };
  job.count = static_cast<int>(pending.size());
  job.fingerprint = Fingerprint(slots);
  job.run = [&](int t) {
    const Task& task = pending[t];
    ReplicateRecord& record = *slots[t];
    record.start_unix_s = objectives::farm::UnixNow();
    const ProbeOutcome o = groups_[task.group].probe->Run(
        models[static_cast<size_t>(task.candidate) * g + task.group], record.seed);
    record.status = o.status, record.values = o.values, record.wall_time_s = o.wall_time_s;
    record.end_unix_s = std::max(record.start_unix_s, objectives::farm::UnixNow());
    record.host = objectives::farm::HostName(), record.rank = objectives::farm::Rank();
  };
  job.save = [&](int t) { return SaveOutcome(*slots[t]); };
  job.load = [&](int t, const std::string& bytes) { LoadOutcome(bytes, slots[t]); };
  job.done = [&](int t) {
    std::string error;
    if (journal_ && !journal_->Append(*slots[t], &error)) {
      std::lock_guard lock(error_mutex);
      std::string& first = journal_errors[pending[t].candidate];
      if (first.empty()) first = error;
    }
  };
  objectives::farm::RunBatch(job, {.threads = options_.workers,
                                   .run_time_limit_s = options_.run_time_limit_s});
  for (const std::string& e : journal_errors)
    if (journal_failure_.empty() && !e.empty()) journal_failure_ = e;
  // Every target's replicate values first, so the pooled spread includes this batch.
  std::vector<std::vector<TargetSample>> samples(n);
  for (int c = 0; c < n; ++c) {
    if (!infeasible[c].empty()) continue;
    for (const TargetBinding& target : targets_) samples[c].push_back(Sample(batch[c], target));
    if (pooled)
      for (size_t k = 0; k < targets_.size(); ++k) pool_[k].Add(samples[c][k].values);
  }
  std::vector<CandidateResult> results;
  for (int c = 0; c < n; ++c) {
    CandidateResult result = Summarise(samples[c], infeasible[c], replicates, pooled);
    result.replicates_reused = reused[c];
    int run = 0;
    for (const Task& t : pending) run += t.candidate == c;
    result.replicates_run = run;
    result.journal_error = journal_errors[c].empty() ? journal_failure_ : journal_errors[c];
    results.push_back(std::move(result));
  }
  return results;
}

TargetEvaluator::TargetSample TargetEvaluator::Sample(const CandidateRuns& runs,
                                                      const TargetBinding& target) const {
  TargetSample s;
  for (const ReplicateRecord& r : runs.runs[target.group]) {
    const auto it = r.values.find(target.observable);
    if (r.ok() && it != r.values.end()) s.values.push_back(it->second);
    else if (s.failure.empty()) s.failure = r.ok() ? "no_" + target.observable : r.status;
  }
  return s;
}

void TargetEvaluator::Pool::Add(const std::vector<double>& values, int sign) {
  if (values.size() < 2) return;
  const objectives::Summary s = objectives::Summarise(values);
  squares += sign * s.stddev * s.stddev * (s.n - 1);
  dof += sign * (s.n - 1);
  if (dof <= 0) squares = 0, dof = 0;  // rounding must not leave a negative remainder
}

CandidateResult TargetEvaluator::Summarise(const std::vector<TargetSample>& samples,
                                           const std::string& infeasible, int replicates,
                                           bool pooled) const {
  CandidateResult result;
  if (!infeasible.empty()) {
    result.status = InfeasibleStatus(infeasible);
    result.targets.assign(targets_.size(), TargetValue{0, 0, 0, result.status});
    return result;
  }
  for (size_t k = 0; k < targets_.size(); ++k) {
    const objectives::Summary s = objectives::Summarise(samples[k].values);
    TargetValue value{s.mean, s.sem, s.n, "ok"};
    if (pooled && options_.pool_spread && pool_[k].dof > 0 && s.n > 0)
      value.sem = std::sqrt(pool_[k].squares / pool_[k].dof / s.n);
    if (s.n < 1 || 2 * s.n < replicates)
      value.status = samples[k].failure.empty() ? "no_value" : samples[k].failure;
    if (result.status == "ok" && value.status != "ok") result.status = value.status;
    result.targets.push_back(value);
  }
  return result;
}

}  // namespace demcal::calibrate
