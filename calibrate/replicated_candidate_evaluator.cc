#include "calibrate/replicated_candidate_evaluator.h"

#include <cmath>

namespace demcal::calibrate {

std::vector<CandidateResult> ReplicatedCandidateEvaluator::EvaluateBatch(
    const std::vector<std::vector<double>>& si_parameters) {
  std::vector<CandidateResult> out;
  for (const std::vector<double>& p : si_parameters) {
    CandidateResult c;
    const Evaluation& e = evaluations_.emplace_back(evaluator_->Evaluate(p, &c.journal_error));
    c.replicates_reused = e.reused;
    c.replicates_run = static_cast<int>(e.runs.size()) - e.reused;
    TargetValue t{e.summary.mean, e.summary.sem, e.summary.n, e.ok() ? "ok" : e.status};
    if (t.status == "ok" && !e.ok()) t.status = "too_few_replicates";
    c.status = t.status;
    c.targets = {t};
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace demcal::calibrate
