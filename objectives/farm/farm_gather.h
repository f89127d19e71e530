#pragma once
// Inside objectives/farm/ only: how farm.h's calls behave inside RunGathered's tasks
// (farm_gather.cc). A task's call is handed to the coordinating thread, which makes it (with the
// other tasks' calls of the same round) and hands the answer back; outside a gathering these
// return false and the caller makes the call itself (the *Here functions).
#include <cstdint>
#include <string>

#include "objectives/farm/farm.h"

namespace demcal::objectives::farm {

bool GatherBatch(const Job& job, const Options& options);
bool GatherRendezvous(uint64_t fingerprint);
bool GatherShare(std::string* bytes);

// The calls themselves, on this thread (farm.cc, farm_ranks.cc).
void RunBatchHere(const Job& job, const Options& options);
void RendezvousHere(uint64_t fingerprint);
void ShareHere(std::string* bytes);

}  // namespace demcal::objectives::farm
