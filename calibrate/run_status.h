#pragma once
// The statuses a replicate run can end with (ProbeOutcome::status, a journal record's "status"):
// "ok", how the DEM run ended (core::TerminationName) and what an experiment found missing.
// A journal record with any other status was not written by demcal and is refused.
#include <string>
#include <vector>

namespace demcal::calibrate {

const std::vector<std::string>& RunStatusNames();
bool IsRunStatus(const std::string& status);

}  // namespace demcal::calibrate
