#pragma once
// What a virtual experiment returns to its caller (the typed front door, run_experiment.h): how
// it ended, how many replicates succeeded, its headline values as mean ± standard error over
// those replicates, and the experiment's own result (AorResult, DischargeResult,
// SegregationResult: every run, for callers that know which experiment they ran). result.json
// is written from the same numbers; it is an output, not the way to read them.
//
//   ExperimentResult r = RunExperimentFile(file, context, log);
//   if (r.status == ExperimentStatus::kOk) use(r.Value("angle_deg")->mean, ...->sem);
//   if (const AorResult* aor = r.Detail<AorResult>()) ... aor->runs ...;
#include <any>
#include <string>
#include <vector>

#include "objectives/common/replicates.h"

namespace demcal::workflow {

enum class ExperimentStatus {
  kOk,                 // at least one replicate gave its measurement
  kRunFailed,          // no replicate did (each run's status says why)
  kInvalidInput,       // the file or its section was refused; nothing ran
  kOutputUnavailable,  // the output folder could not be created or is in use; nothing ran
  kOutputError,        // the runs ended but an output file could not be written
};

// The process exit code of `demcal experiment` for a status (outputs/exit_codes.h).
int ExitCodeOf(ExperimentStatus status);

// A measured value: mean, standard deviation and standard error over summary.n replicates (no
// mean for n = 0, no sem for n < 2). The name carries the unit ("angle_deg").
struct NamedEstimate {
  std::string name;
  objectives::Summary value;
};

struct ExperimentResult {
  ExperimentStatus status = ExperimentStatus::kInvalidInput;
  std::string message;     // why, when the input was refused or the output folder unavailable
  std::string experiment;  // "aor", "discharge", "segregation"
  int replicates = 0;
  int replicates_ok = 0;
  std::vector<NamedEstimate> values;  // the experiment's headline values, in a fixed order
  std::any detail;                    // the experiment's own result type (see above)

  // The value named `name`, or nullptr.
  const objectives::Summary* Value(const std::string& name) const;
  template <class T>
  const T* Detail() const {
    return std::any_cast<T>(&detail);
  }
};

}  // namespace demcal::workflow
