#pragma once
// ReplicateProgress: one progress line with an ETA for replicate runs that proceed side by
// side, e.g.
//   [demcal] aor: 2/4 replicates done, 63.0%  elapsed 21.4 s  ETA 12.6 s
// Each replicate reports its own fraction (simulated time over its expected end); the line
// shows their mean and assumes the rate so far continues. At most one line per interval. A
// replicate's fraction never falls back: its expected end can move later (a settling heap whose
// energy stops decaying for a while, settle_eta.h), and a percentage that drops from 86 % to
// 44 % tells a user less than one that holds while the ETA, elapsed × (1 − f) / f, grows.
//
// Thread-safety: Update and Finish may be called from any replicate's thread.
#include <chrono>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace demcal::workflow {

class ReplicateProgress {
 public:
  ReplicateProgress(std::ostream& out, std::string label, int replicates, bool enabled,
                    double interval_s = 2.0);
  void Update(int replicate, double simulated_s, double expected_end_s);
  void Finish(int replicate);

 private:
  void PrintLocked(double elapsed_s);
  std::ostream& out_;
  std::string label_;
  bool enabled_;
  double interval_s_;
  std::mutex mutex_;
  std::vector<double> fraction_;
  int done_ = 0;
  std::chrono::steady_clock::time_point start_;
  double last_print_s_ = 0;
};

}  // namespace demcal::workflow
