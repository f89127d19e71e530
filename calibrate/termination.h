#pragma once
// Termination: how a calibration, and the optimiser inside it, ended. Code decides on the enum;
// files (result.json, evaluations and clump-count tables, reports) carry its name, and
// TerminationName / ParseTermination are the one place the two meet. The names are part of those
// file formats: never rename one.
//
//   if (summary.termination == Termination::kWithinNoise) ...;
//   json["termination"] = TerminationName(summary.termination);
#include <string_view>

namespace demcal::calibrate {

enum class Termination {
  kWithinNoise,  // "within_noise": a candidate matches every target within noise
  kConverged,    // "converged": tolerance reached without a match within noise
  kOutOfRange,   // "out_of_range": the measurement lies outside what the bounds reach
  kBudget,       // "budget": the candidate budget ran out before a match
  kFailed,       // "failed": no candidate gave a value, or the optimiser could not run
  kInvalid,      // "invalid": the options or targets were refused before any run
};

const char* TerminationName(Termination t);
// False (and *out untouched) for a name that is none of the above.
bool ParseTermination(std::string_view name, Termination* out);

}  // namespace demcal::calibrate
