#pragma once
// CandidateEvaluator: the simulations behind a calibration, as an interface the driver
// (calibration.h) calls with a batch of candidate parameter sets (SI values, one per parameter
// of the ParameterSpace) and which answers, per candidate, every target's simulated mean and
// standard error (over its replicates), or a status saying why there is no value. An
// implementation runs the candidates of a batch (and their replicates) concurrently, journals
// every replicate, and reads finished ones back from the journal on resume.
//
//   class MyEvaluator final : public CandidateEvaluator {
//     std::vector<CandidateResult> EvaluateBatch(const std::vector<std::vector<double>>& p)
//     override;
//   };
//
// Thread-safety: the driver calls EvaluateBatch from one thread, one batch at a time.
#include <optional>
#include <string>
#include <vector>

namespace demcal::calibrate {

// One target's simulated value at one candidate.
struct TargetValue {
  double mean = 0;            // observable unit
  double sem = 0;             // standard error of the mean over replicates, >= 0
  int replicates = 0;         // replicates that gave a value
  std::string status = "ok";  // "ok", or why there is no value ("not_settled", ...)
  bool ok() const;            // status "ok", replicates >= 1, finite mean and sem
};

struct CandidateResult {
  std::vector<TargetValue> targets;  // one per target, in the study's order
  std::string status = "ok";         // "ok", or the first failure
  int replicates_run = 0;            // simulated now
  int replicates_reused = 0;         // found in the journal
  std::string journal_error;         // first failure to write the journal ("" if none)
  bool ok() const;                   // status "ok" and every target ok
};

// The status of a candidate the parameter space refused before any run ("infeasible: " + why),
// and the test for it: a refused candidate fails as a whole, whatever its targets say.
std::string InfeasibleStatus(const std::string& why);
bool IsInfeasibleStatus(const std::string& status);

class CandidateEvaluator {
 public:
  virtual ~CandidateEvaluator() = default;
  // One result per candidate, in order. Must not throw for a failed simulation: that is a
  // status.
  virtual std::vector<CandidateResult> EvaluateBatch(
      const std::vector<std::vector<double>>& si_parameters) = 0;
  // Re-runs the last candidate evaluated with these parameters at `replicates` replicates in
  // all (those already run are reused), its sem then from its own spread. For a candidate too
  // noisy to confirm a match (TrialResult::Inconclusive). Empty: this evaluator cannot (the
  // default) or no such candidate was evaluated.
  virtual std::optional<CandidateResult> AddReplicates(const std::vector<double>& si_parameters,
                                                       int replicates) {
    (void)si_parameters, (void)replicates;
    return std::nullopt;
  }
};

}  // namespace demcal::calibrate
