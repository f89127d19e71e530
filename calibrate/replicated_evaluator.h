#pragma once
// ReplicatedEvaluator: the observable at one candidate parameter set, as the mean ± standard
// error of R replicate runs. Replicate r uses the same seed for every candidate (common random
// numbers: differences between candidates are then not packing noise). Replicates run side by
// side (objectives::RunReplicates); each finished one goes to the journal at once, and one found
// in the journal is not run again.
//
// Parameters are physical (full-scale) values: they are written into the model first, then
// `prepare` (if set) turns it into the simulated model — typically the fidelity (size
// coarse-graining, stiffness reduction, Γ carried by the Cohesion number), so a calibrated Γ is
// the real one, not the scaled one.
//
//   ReplicatedEvaluator evaluator(model, space, observable, {.replicates = 3, .seed = 7}, &journal);
//   Evaluation e = evaluator.Evaluate({0.3});
//   if (e.ok()) use(e.summary.mean, e.summary.sem);
//
// Thread-safety: one Evaluate at a time (it runs its replicates in parallel itself).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "calibrate/evaluation_journal.h"
#include "calibrate/observable.h"
#include "calibrate/parameter_space.h"
#include "core/scene.h"
#include "objectives/common/replicates.h"

namespace demcal::calibrate {

struct EvaluatorOptions {
  int replicates = 2;  // runs per candidate, >= 1
  uint64_t seed = 1;   // base seed of the replicates
  int workers = 0;     // replicates side by side (0: all cores)
  std::function<void(core::Scene*)> prepare;  // applied after the parameters (e.g. fidelity)
};

struct Evaluation {
  int index = 0;                       // 0, 1, ... in the order the optimiser asked
  std::vector<double> parameters;      // SI values
  std::vector<ReplicateRecord> runs;   // one per replicate
  objectives::Summary summary;         // over the replicates that gave a value
  int reused = 0;                      // replicates found in the journal
  std::string status = "ok";           // "ok", or the first failed replicate's status
  // A candidate counts if at least half of its replicates (and at least one) gave a value.
  bool ok() const { return summary.n >= 1 && 2 * summary.n >= static_cast<int>(runs.size()); }
};

class ReplicatedEvaluator {
 public:
  ReplicatedEvaluator(const core::Scene& model, const ParameterSpace& space,
                      const Observable& observable, EvaluatorOptions options,
                      EvaluationJournal* journal);
  // Runs (or reads from the journal) every replicate of this candidate. A journal that cannot
  // be written is reported in *journal_error; the values are still returned.
  Evaluation Evaluate(const std::vector<double>& parameters, std::string* journal_error = nullptr);
  const EvaluatorOptions& options() const { return options_; }

 private:
  const core::Scene& model_;
  const ParameterSpace& space_;
  const Observable& observable_;
  EvaluatorOptions options_;
  EvaluationJournal* journal_;
  int evaluations_ = 0;
};

}  // namespace demcal::calibrate
