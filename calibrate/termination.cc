#include "calibrate/termination.h"

namespace demcal::calibrate {
namespace {

constexpr Termination kAll[] = {Termination::kWithinNoise, Termination::kConverged,
                                Termination::kOutOfRange,  Termination::kBudget,
                                Termination::kFailed,      Termination::kInvalid};

}  // namespace

const char* TerminationName(Termination t) {
  switch (t) {
    case Termination::kWithinNoise: return "within_noise";
    case Termination::kConverged: return "converged";
    case Termination::kOutOfRange: return "out_of_range";
    case Termination::kBudget: return "budget";
    case Termination::kFailed: return "failed";
    case Termination::kInvalid: return "invalid";
  }
  return "unknown";
}

bool ParseTermination(std::string_view name, Termination* out) {
  for (Termination t : kAll)
    if (name == TerminationName(t)) return *out = t, true;
  return false;
}

}  // namespace demcal::calibrate
