#include "experiments/common/replicate_progress.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "outputs/progress_reporter.h"

namespace demcal::workflow {

ReplicateProgress::ReplicateProgress(std::ostream& out, std::string label, int replicates,
                                     bool enabled, double interval_s)
    : out_(out),
      label_(std::move(label)),
      enabled_(enabled),
      interval_s_(interval_s),
      fraction_(std::max(replicates, 1), 0.0),
      start_(std::chrono::steady_clock::now()) {}

void ReplicateProgress::Update(int replicate, double simulated_s, double expected_end_s) {
  if (!enabled_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::lock_guard<std::mutex> lock(mutex_);
  if (expected_end_s > 0)
    fraction_[replicate] =
        std::max(fraction_[replicate], std::clamp(simulated_s / expected_end_s, 0.0, 0.99));
  if (elapsed - last_print_s_ < interval_s_) return;
  last_print_s_ = elapsed;
  PrintLocked(elapsed);
}

void ReplicateProgress::Finish(int replicate) {
  std::lock_guard<std::mutex> lock(mutex_);
  fraction_[replicate] = 1.0;
  ++done_;
}

void ReplicateProgress::PrintLocked(double elapsed_s) {
  const double mean =
      std::accumulate(fraction_.begin(), fraction_.end(), 0.0) / fraction_.size();
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.1f%%", 100 * mean);
  out_ << "[demcal] " << label_ << ": " << done_ << "/" << fraction_.size()
       << " replicates done, " << percent << "  elapsed " << FormatDuration(elapsed_s);
  if (mean > 0.01) out_ << "  ETA " << FormatDuration(elapsed_s * (1 - mean) / mean);
  out_ << "\n" << std::flush;
}

}  // namespace demcal::workflow
