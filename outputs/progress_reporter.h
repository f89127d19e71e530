#pragma once
// ProgressReporter: progress and ETA of a long run as one line on a stream (stderr in the CLI),
// at most one line per `interval_s` of wall time, e.g.
//   [demcal]  42.0%  t = 0.2100 / 0.5000 s  3000 particles  elapsed 8.4 s  ETA 11.6 s
// Short runs print nothing: the first line comes only after `interval_s` of wall time. The ETA
// assumes the simulated-time rate so far continues (DEM cost per step is roughly constant once
// the neighbour list is warm).
//
// Thread-safety: one reporter per run, called from one thread at a time.
//
// Usage:
//   ProgressReporter progress(std::cerr, duration_s, {});
//   ... every few steps: progress.Update(sim.time_s(), sim.particles().Size());
#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace demcal::workflow {

struct ProgressSample {
  double simulated_time_s = 0;
  double duration_s = 0;
  double start_time_s = 0;  // simulated time when the wall clock started (a restarted run)
  int64_t particles = 0;
  double elapsed_wall_s = 0;
};

// Wall time still needed if the rate so far continues; negative if it cannot be estimated yet.
double EstimateRemainingWallTime(const ProgressSample& sample);
// The progress line for one sample (no newline).
std::string FormatProgressLine(const ProgressSample& sample);
// "8.4 s", "3 min 12 s", "1 h 05 min".
std::string FormatDuration(double seconds);

class ProgressReporter {
 public:
  struct Options {
    double interval_s = 2.0;  // minimum wall time between lines, > 0
    bool enabled = true;      // false: print nothing (--quiet)
    double start_time_s = 0;  // simulated time at the start (> 0 for a restarted run)
  };

  ProgressReporter(std::ostream& out, double duration_s, Options options);

  // Prints a line if `interval_s` has passed since the start or the previous line. Cheap enough
  // to call every few steps (one clock read).
  void Update(double simulated_time_s, int64_t particles);
  int lines_printed() const { return lines_; }

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& out_;
  double duration_s_;
  Options options_;
  Clock::time_point start_;
  Clock::time_point last_line_;
  int lines_ = 0;
};

}  // namespace demcal::workflow
