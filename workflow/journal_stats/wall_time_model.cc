#include "workflow/journal_stats/wall_time_model.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <sstream>
#include <utility>

namespace demcal::workflow {
namespace {

struct Batch {
  double first_start = INFINITY, last_end = -INFINITY;
  std::vector<std::pair<double, double>> runs;  // start, time: sorted by start = queue order
};

}  // namespace

double ListScheduleMakespan(const std::vector<double>& times, int slots) {
  // Free times of the slots, earliest first; equal free times take the lowest slot, which does
  // not change the makespan.
  std::priority_queue<double, std::vector<double>, std::greater<double>> free_at;
  for (int k = 0; k < std::max(1, slots); ++k) free_at.push(0);
  double makespan = 0;
  for (const double t : times) {
    const double start = free_at.top();
    free_at.pop();
    free_at.push(start + t);
    makespan = std::max(makespan, start + t);
  }
  return makespan;
}

WallTimeModel ModelWallTime(const std::vector<JournalRun>& runs, const std::vector<int>& ranks) {
  WallTimeModel m;
  // A batch: the runs that share batch_unix_s, whatever their journal (calibrations run
  // together share the farm's batch, farm::RunGathered), or a run of its own without one.
  std::map<std::pair<double, size_t>, Batch> batches;
  double first = INFINITY, last = -INFINITY;
  for (size_t k = 0; k < runs.size(); ++k) {
    const JournalRun& r = runs[k];
    if (!r.timed) continue;
    ++m.runs;
    m.run_time_s += r.time_s;
    first = std::min(first, r.start), last = std::max(last, r.end);
    Batch& b = batches[{r.batch, r.batch > 0 ? 0 : k + 1}];
    b.first_start = std::min(b.first_start, r.start);
    b.last_end = std::max(b.last_end, r.end);
    b.runs.emplace_back(r.start, r.time_s);
  }
  m.batches = static_cast<int>(batches.size());
  if (m.runs == 0) return m;
  m.measured_span_s = last - first;
  std::vector<std::pair<double, double>> spans;
  for (auto& [key, b] : batches) {
    std::sort(b.runs.begin(), b.runs.end());
    spans.emplace_back(b.first_start, b.last_end);
  }
  m.between_batches_s = std::max(0.0, m.measured_span_s - CoveredSeconds(spans));
  for (const int n : ranks) {
    WallTimePrediction p{n, std::max(1, n - 1), m.between_batches_s};
    for (const auto& [key, b] : batches) {
      std::vector<double> times;
      for (const auto& run : b.runs) times.push_back(run.second);
      p.wall_span_s += ListScheduleMakespan(times, p.slots);
    }
    m.predictions.push_back(p);
  }
  return m;
}

std::string WallTimeModelText(const WallTimeModel& m) {
  std::ostringstream out;
  out.precision(4);
  out << "wall-time model: " << m.runs << " timed runs in " << m.batches
      << " batches, batches in sequence, each run its measured time on a slot of its own\n"
      << "measured wall span (s): " << m.measured_span_s << "\n"
      << "measured time between batches (s): " << m.between_batches_s << "\n";
  for (const WallTimePrediction& p : m.predictions)
    out << "predicted wall span at " << p.ranks << " ranks (" << p.slots
        << " runs at once) (s): " << p.wall_span_s << "\n";
  return out.str();
}

nlohmann::ordered_json WallTimeModelJson(const WallTimeModel& m) {
  nlohmann::ordered_json j{{"timed_runs", m.runs},
                           {"batches", m.batches},
                           {"measured_wall_span_s", m.measured_span_s},
                           {"between_batches_s", m.between_batches_s},
                           {"run_time_s", m.run_time_s},
                           {"predictions", nlohmann::ordered_json::array()}};
  for (const WallTimePrediction& p : m.predictions)
    j["predictions"].push_back(
        {{"ranks", p.ranks}, {"runs_at_once", p.slots}, {"wall_span_s", p.wall_span_s}});
  return j;
}

}  // namespace demcal::workflow
