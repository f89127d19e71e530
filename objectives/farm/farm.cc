#include "objectives/farm/farm.h"

#include <unistd.h>

#include <chrono>

#include "objectives/common/replicates.h"
#include "objectives/farm/farm_gather.h"
#include "objectives/farm/farm_ranks.h"

namespace demcal::objectives::farm {

const std::string& HostName() {
  static const std::string name = [] {
    char buffer[256] = {};
    return ::gethostname(buffer, sizeof buffer - 1) == 0 ? std::string(buffer) : std::string();
  }();
  return name;
}

double UnixNow() {
  const auto since = std::chrono::system_clock::now().time_since_epoch();
  return std::chrono::duration_cast<std::chrono::microseconds>(since).count() * 1e-6;
}

void RunBatch(const Job& job, const Options& options) {
  if (!GatherBatch(job, options)) RunBatchHere(job, options);
}

void RunBatchHere(const Job& job, const Options& options) {
  if (job.started) job.started(UnixNow());
  if (job.count <= 0 && !Farmed()) return;
  if (!Farmed()) {
    RunReplicates(job.count, 0, options.threads, [&](int t, uint64_t) {
      job.run(t);
      if (job.done) job.done(t);
    });
    return;
  }
  RunBatchOverRanks(job, options);
}

}  // namespace demcal::objectives::farm
