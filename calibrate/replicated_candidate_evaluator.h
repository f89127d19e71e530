#pragma once
// ReplicatedCandidateEvaluator: the CandidateEvaluator of a single-target study, adapting a
// ReplicatedEvaluator (one observable, R replicates with their journal). Candidates of a batch
// are evaluated one after another, each with its replicates side by side (the replicated
// evaluator's own parallelism). It keeps every Evaluation, in order, for the single-target
// outputs (calibrate command, evaluations.csv).
//
//   ReplicatedCandidateEvaluator adapter(&replicated);
//   CalibrationSummary s = Calibrate(adapter, space, {target}, options);
//   const std::vector<Evaluation>& history = adapter.evaluations();
//
// Thread-safety: as ReplicatedEvaluator (one batch at a time).
#include <vector>

#include "calibrate/candidate_evaluator.h"
#include "calibrate/replicated_evaluator.h"

namespace demcal::calibrate {

class ReplicatedCandidateEvaluator final : public CandidateEvaluator {
 public:
  explicit ReplicatedCandidateEvaluator(ReplicatedEvaluator* evaluator) : evaluator_(evaluator) {}
  std::vector<CandidateResult> EvaluateBatch(
      const std::vector<std::vector<double>>& si_parameters) override;
  const std::vector<Evaluation>& evaluations() const { return evaluations_; }

 private:
  ReplicatedEvaluator* evaluator_;
  std::vector<Evaluation> evaluations_;
};

}  // namespace demcal::calibrate
