#pragma once
// TargetEvaluator: the CandidateEvaluator of a multi-target study. Targets read observables of
// experiment runs; a run group is one experiment (a probe with its full-scale model) under one
// condition, so two targets of the same heap (its angle and its crest drop) share its runs.
// For each candidate of a batch and each group: the parameters are written into the model under
// the group's condition (ParameterSpace::Apply: per-condition parameters, curves), then
// `prepare` turns it into the simulated model (the fidelity: coarse-graining, stiffness, Γ at
// constant Cohesion number). Replicate r uses the same seed in every group and for every
// candidate (common random numbers). All runs of a batch — candidates × groups × replicates —
// go side by side, one per worker (objectives/farm: threads of this process, or the ranks of an
// MPI job, where every rank ends the batch with the same records); each finished run goes to the
// journal at once (group key, parameters, replicate, seed, with where and when it ran), and a run
// found there is not repeated.
//
// A candidate that breaks a declared constraint, or whose curve gives no valid property at a
// group's condition, is infeasible without running. A target has a value when at least half of
// its group's replicates (and at least one) gave one.
//
//   TargetEvaluator evaluator(space, groups, targets, {.replicates = 2, .seed = 7}, &journal);
//   CalibrationSummary s = Calibrate(evaluator, space, targets_measured, options);
//
// Thread-safety: one EvaluateBatch at a time (it parallelises inside).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "calibrate/candidate_evaluator.h"
#include "calibrate/condition.h"
#include "calibrate/evaluation_journal.h"
#include "calibrate/experiment_probe.h"
#include "calibrate/parameter_space.h"
#include "core/scene/scene.h"

namespace demcal::calibrate {

struct RunGroup {
  std::string key;                        // journal group, unique: "aor_bp.json|coating=0.5"
  const ExperimentProbe* probe = nullptr;  // not owned
  core::Scene model;                       // full scale, before the parameters
  ParameterSpace space;                    // the study's, resolved to this model's materials
  Condition condition;
  std::function<void(core::Scene*)> prepare;  // applied after the parameters (fidelity)
};

struct TargetBinding {
  int group = 0;           // index into the groups
  std::string observable;  // one the group's probe reports
};

struct TargetEvaluatorOptions {
  int replicates = 2;  // runs per candidate and group, >= 1
  uint64_t seed = 1;   // base seed of the replicates
  int workers = 0;     // runs side by side (0: all cores; per rank under mpirun, farm.h)
  double run_time_limit_s = 0;  // under mpirun: a run copied to another rank after (0: auto)
  // sem of a target from the replicate spread pooled over every candidate evaluated so far
  // (pooled variance, Σ(n_i − 1)s_i² / Σ(n_i − 1)), not from this candidate's replicates alone:
  // with R = 2 one candidate's spread has one degree of freedom and swings by a factor 10 from
  // candidate to candidate, which would make "within noise" a coin toss. Packing noise depends
  // little on the parameters over a calibration's range, so pooling is the better estimate.
  // A candidate given more replicates (AddReplicates) leaves the pool and uses its own spread.
  bool pool_spread = true;
};

// What one candidate gave, per group and replicate (for evaluations.csv and the plots).
struct CandidateRuns {
  std::vector<double> parameters;
  std::vector<std::vector<ReplicateRecord>> runs;  // [group][replicate]
  bool pooled = true;  // its spread is in the pool (false once it has replicates added)
};

class TargetEvaluator final : public CandidateEvaluator {
 public:
  TargetEvaluator(const ParameterSpace& space, std::vector<RunGroup> groups,
                  std::vector<TargetBinding> targets, TargetEvaluatorOptions options,
                  EvaluationJournal* journal);
  std::vector<CandidateResult> EvaluateBatch(
      const std::vector<std::vector<double>>& si_parameters) override;
  std::optional<CandidateResult> AddReplicates(const std::vector<double>& si_parameters,
                                               int replicates) override;
  const std::vector<CandidateRuns>& history() const { return history_; }
  const std::vector<RunGroup>& groups() const { return groups_; }

 private:
  struct Task;
  struct TargetSample {
    std::vector<double> values;  // of the replicates that gave one
    std::string failure;         // the first replicate's reason for none
  };
  struct Pool {
    double squares = 0;  // Σ (n_i − 1) s_i²
    int dof = 0;         // Σ (n_i − 1)
    void Add(const std::vector<double>& values, int sign = 1);
    void Remove(const std::vector<double>& values) { Add(values, -1); }
  };
  // Runs (or finds in the journal) `replicates` replicates per group of each candidate; sem
  // from the pool (`pooled`, which then takes their spread) or from each candidate's own.
  // `prior`: the one candidate's earlier runs, reused (the journal may be off).
  std::vector<CandidateResult> Run(const std::vector<std::vector<double>>& si_parameters,
                                   int replicates, bool pooled, std::vector<CandidateRuns>* runs,
                                   const CandidateRuns* prior = nullptr);
  TargetSample Sample(const CandidateRuns& runs, const TargetBinding& target) const;
  CandidateResult Summarise(const std::vector<TargetSample>& samples, const std::string& infeasible,
                            int replicates, bool pooled) const;

  const ParameterSpace& space_;
  std::vector<RunGroup> groups_;
  std::vector<TargetBinding> targets_;
  TargetEvaluatorOptions options_;
  EvaluationJournal* journal_;
  std::string journal_failure_;  // the first failed journal write: nothing runs after it
  std::vector<CandidateRuns> history_;
  std::vector<Pool> pool_;  // per target
};

}  // namespace demcal::calibrate
