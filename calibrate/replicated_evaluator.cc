#include "calibrate/replicated_evaluator.h"

#include <mutex>

namespace demcal::calibrate {

ReplicatedEvaluator::ReplicatedEvaluator(const core::Scene& model, const ParameterSpace& space,
                                         const Observable& observable, EvaluatorOptions options,
                                         EvaluationJournal* journal)
    : model_(model), space_(space), observable_(observable), options_(options), journal_(journal) {}

Evaluation ReplicatedEvaluator::Evaluate(const std::vector<double>& parameters,
                                         std::string* journal_error) {
  Evaluation e;
  e.index = evaluations_++;
  e.parameters = parameters;
  e.runs.resize(options_.replicates);
  core::Scene model = model_;
  space_.Apply(parameters, &model);
  if (options_.prepare) options_.prepare(&model);
  std::vector<int> pending;
  for (int r = 0; r < options_.replicates; ++r) {
    const uint64_t seed = objectives::ReplicateSeed(options_.seed, r);
    const ReplicateRecord* done = journal_ ? journal_->Find(parameters, r, seed) : nullptr;
    if (done) {
      e.runs[r] = *done;
      ++e.reused;
    } else {
      e.runs[r] = {parameters, r, seed, "pending", 0, 0};
      pending.push_back(r);
    }
  }
  std::mutex error_mutex;
  objectives::RunReplicates(
      static_cast<int>(pending.size()), 0, options_.workers, [&](int k, uint64_t) {
        ReplicateRecord& record = e.runs[pending[k]];
        const ReplicateOutcome o = observable_.Run(model, record.seed);
        record.status = o.status, record.value = o.value, record.wall_time_s = o.wall_time_s;
        std::string error;
        if (journal_ && !journal_->Append(record, &error) && journal_error) {
          std::lock_guard lock(error_mutex);
          if (journal_error->empty()) *journal_error = error;
        }
      });
  std::vector<double> values;
  for (const ReplicateRecord& r : e.runs) {
    if (r.ok()) values.push_back(r.value);
    else if (e.status == "ok") e.status = r.status;
  }
  e.summary = objectives::Summarise(values);
  if (e.ok()) e.status = "ok";
  return e;
}

}  // namespace demcal::calibrate
