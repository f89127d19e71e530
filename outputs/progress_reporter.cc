#include "outputs/progress_reporter.h"

#include <cmath>
#include <cstdio>

namespace demcal::workflow {

double EstimateRemainingWallTime(const ProgressSample& s) {
  const double done = s.simulated_time_s - s.start_time_s;  // in this process's wall time
  if (!(done > 0) || !(s.elapsed_wall_s > 0) || !(s.duration_s > 0)) return -1;
  const double remaining_sim = std::max(0.0, s.duration_s - s.simulated_time_s);
  return remaining_sim * s.elapsed_wall_s / done;
}

std::string FormatDuration(double seconds) {
  char buf[48];
  if (seconds < 0) return "?";
  if (seconds < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  } else if (seconds < 3600) {
    const long total = std::lround(seconds);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", total / 60, total % 60);
  } else {
    const long minutes = std::lround(seconds / 60);
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", minutes / 60, minutes % 60);
  }
  return buf;
}

std::string FormatProgressLine(const ProgressSample& s) {
  const double percent =
      s.duration_s > 0 ? 100.0 * std::min(1.0, s.simulated_time_s / s.duration_s) : 100.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "[demcal] %5.1f%%  t = %.4g / %.4g s  %lld particles  elapsed ",
                percent, s.simulated_time_s, s.duration_s, static_cast<long long>(s.particles));
  return std::string(buf) + FormatDuration(s.elapsed_wall_s) + "  ETA " +
         FormatDuration(EstimateRemainingWallTime(s));
}

ProgressReporter::ProgressReporter(std::ostream& out, double duration_s, Options options)
    : out_(out),
      duration_s_(duration_s),
      options_(options),
      start_(Clock::now()),
      last_line_(start_) {}

void ProgressReporter::Update(double simulated_time_s, int64_t particles) {
  if (!options_.enabled) return;
  const Clock::time_point now = Clock::now();
  if (std::chrono::duration<double>(now - last_line_).count() < options_.interval_s) return;
  last_line_ = now;
  ProgressSample s;
  s.simulated_time_s = simulated_time_s;
  s.duration_s = duration_s_;
  s.start_time_s = options_.start_time_s;
  s.particles = particles;
  s.elapsed_wall_s = std::chrono::duration<double>(now - start_).count();
  out_ << FormatProgressLine(s) << std::endl;
  ++lines_;
}

}  // namespace demcal::workflow
