#include "workflow/journal_stats/journal_stats.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/io/input_file.h"

namespace demcal::workflow {
namespace {

// The evaluation journal's own cap (calibrate/evaluation_journal.cc).
constexpr size_t kMaxJournalBytes = size_t{256} << 20;

using Run = JournalRun;
constexpr const char* kStageJournalFormat = "demcal-stage-journal/1";  // reproduce's stages.jsonl

bool Fail(std::string* error, const std::string& message) {
  *error = message;
  return false;
}

double Number(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() && std::isfinite(it->get<double>()) ? it->get<double>()
                                                                               : -1;
}

// The timing of `j` (a record, or a stage record's "run") into *r.
void TakeTimes(const nlohmann::json& j, Run* r) {
  r->time_s = std::max(0.0, Number(j, "wall_time_s"));
  r->start = Number(j, "start_unix_s"), r->end = Number(j, "end_unix_s");
  r->timed = r->start > 0 && r->end >= r->start;
  if (r->timed) {
    r->time_s = r->end - r->start;
    r->batch = std::max(0.0, Number(j, "batch_unix_s"));
    r->host = j.value("host", std::string());
    r->rank = std::max(0, static_cast<int>(Number(j, "rank")));
  }
}

// The runs of one journal; false on a line that is not a record. Not a journal at all (another
// .jsonl): true with *is_journal false. In a stage journal only the records with a timed "run"
// are runs (the stages' own records are not simulations).
bool ReadRuns(const std::string& path, int index, std::vector<Run>* runs, bool* is_journal,
              std::string* error) {
  std::string content;
  if (!core::io::ReadRegularFile(path, "journal", kMaxJournalBytes, {}, &content, error))
    return false;
  content.resize(content.rfind('\n') == std::string::npos ? 0 : content.rfind('\n') + 1);
  std::istringstream lines(content);
  std::string line;
  *is_journal = false;
  bool stages = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    const std::string at = path + ":" + std::to_string(number) + ": ";
    if (number == 1) {
      const std::string format = j.is_object() ? j.value("format", "") : "";
      stages = format == kStageJournalFormat;
      *is_journal = stages || format.rfind("demcal-journal/", 0) == 0;
      if (!*is_journal) return true;
      continue;
    }
    Run r;
    r.journal = index;
    if (stages) {
      if (!j.is_object() || !j.contains("key")) return Fail(error, at + "not a stage record");
      const nlohmann::json* result = j.contains("result") ? &j["result"] : nullptr;
      if (!result || !result->is_object() || !result->contains("run")) continue;
      TakeTimes((*result)["run"], &r);
      if (r.timed) runs->push_back(std::move(r));
      continue;
    }
    if (!j.is_object() || !j.contains("seed")) return Fail(error, at + "not a journal record");
    TakeTimes(j, &r);
    runs->push_back(std::move(r));
  }
  return true;
}

}  // namespace

double CoveredSeconds(std::vector<std::pair<double, double>> intervals) {
  std::sort(intervals.begin(), intervals.end());
  double total = 0, from = 0, to = -1;
  for (const auto& [a, b] : intervals) {
    if (a > to) {
      total += std::max(0.0, to - from);
      from = a, to = b;
    } else {
      to = std::max(to, b);
    }
  }
  return total + std::max(0.0, to - from);
}

bool ReadJournalRuns(const std::string& dir, std::vector<JournalRun>* runs, int* journals,
                     std::string* error) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return Fail(error, dir + ": not a directory");
  std::vector<std::string> paths;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec))
    if (it->path().extension() == ".jsonl" && it->is_regular_file(ec)) paths.push_back(it->path());
  if (ec) return Fail(error, dir + ": cannot list: " + ec.message());
  std::sort(paths.begin(), paths.end());
  runs->clear();
  *journals = 0;
  for (const std::string& path : paths) {
    bool is_journal = false;
    if (!ReadRuns(path, *journals, runs, &is_journal, error)) return false;
    *journals += is_journal;
  }
  if (*journals == 0)
    return Fail(error, dir + ": no evaluation journal (a .jsonl with a demcal-journal header)");
  return true;
}

bool ReadJournalStats(const std::string& dir, JournalStats* stats, std::string* error) {
  std::vector<Run> runs;
  *stats = JournalStats{};
  if (!ReadJournalRuns(dir, &runs, &stats->journals, error)) return false;
  stats->simulations = static_cast<int>(runs.size());
  double first = INFINITY, last = -INFINITY, timed_s = 0;
  // batch -> its longest run; a batch is the runs that share batch_unix_s, whatever their
  // journal (the calibrations reproduce runs together share the farm's batch)
  std::map<std::pair<double, size_t>, double> longest;
  std::map<std::pair<std::string, int>, std::vector<std::pair<double, double>>> by_rank;
  for (size_t k = 0; k < runs.size(); ++k) {
    const Run& r = runs[k];
    stats->run_time_s += r.time_s;
    if (!r.timed) {
      ++stats->untimed;
      continue;
    }
    first = std::min(first, r.start), last = std::max(last, r.end);
    timed_s += r.time_s;
    double& batch = longest[{r.batch, r.batch > 0 ? 0 : k + 1}];
    batch = std::max(batch, r.time_s);
    by_rank[{r.host, r.rank}].emplace_back(r.start, r.end);
  }
  if (!runs.empty()) stats->mean_run_time_s = stats->run_time_s / static_cast<double>(runs.size());
  stats->wall_span_s = last > first ? last - first : 0;
  if (stats->wall_span_s > 0) stats->runs_at_once = timed_s / stats->wall_span_s;
  stats->batches = static_cast<int>(longest.size());
  for (const auto& [key, t] : longest) stats->critical_path_s += t;
  for (const auto& [key, intervals] : by_rank) {
    RankUse use{key.first, key.second, static_cast<int>(intervals.size())};
    for (const auto& [a, b] : intervals) use.run_time_s += b - a;
    if (stats->wall_span_s > 0) {
      use.busy_fraction = CoveredSeconds(intervals) / stats->wall_span_s;
      use.runs_at_once = use.run_time_s / stats->wall_span_s;
    }
    stats->ranks.push_back(use);
  }
  return true;
}

std::string JournalStatsText(const JournalStats& s) {
  std::ostringstream out;
  out.precision(4);
  out << "journals: " << s.journals << "\n"
      << "simulations: " << s.simulations << " (" << s.untimed << " without host, rank and times)\n"
      << "total run time (s): " << s.run_time_s << "\n"
      << "mean run time (s): " << s.mean_run_time_s << "\n"
      << "wall span (s): " << s.wall_span_s << "\n"
      << "critical path, the longest run of each of " << s.batches << " batches (s): "
      << s.critical_path_s << "\n";
  out << "runs at once, timed run time / wall span: " << s.runs_at_once << "\n";
  for (const RankUse& r : s.ranks)
    out << "rank " << r.rank << " on " << (r.host.empty() ? "?" : r.host) << ": " << r.runs
        << " runs, run time (s) " << r.run_time_s << ", busy fraction " << r.busy_fraction
        << ", runs at once " << r.runs_at_once << "\n";
  return out.str();
}

nlohmann::ordered_json JournalStatsJson(const JournalStats& s) {
  nlohmann::ordered_json j{{"format", "demcal-journal-stats/1"},
                           {"journals", s.journals},
                           {"simulations", s.simulations},
                           {"simulations_without_times", s.untimed},
                           {"total_run_time_s", s.run_time_s},
                           {"mean_run_time_s", s.mean_run_time_s},
                           {"wall_span_s", s.wall_span_s},
                           {"batches", s.batches},
                           {"critical_path_s", s.critical_path_s},
                           {"runs_at_once", s.runs_at_once},
                           {"ranks", nlohmann::ordered_json::array()}};
  for (const RankUse& r : s.ranks)
    j["ranks"].push_back({{"host", r.host},
                          {"rank", r.rank},
                          {"runs", r.runs},
                          {"run_time_s", r.run_time_s},
                          {"busy_fraction", r.busy_fraction},
                          {"runs_at_once", r.runs_at_once}});
  return j;
}

}  // namespace demcal::workflow
