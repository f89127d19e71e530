#pragma once
// JournalStats: how a finished (or running) job used its machines, read from its evaluation
// journals (calibrate/evaluation_journal.h): every `*.jsonl` under a folder whose header is a
// demcal-journal (a calibration's journal.jsonl, the calibrations of reproduce, diagnose's
// journal/<hash>.jsonl), and the runs of reproduce's stage journal (stages.jsonl: the records
// whose result carries "run" {host, rank, start_unix_s, end_unix_s, batch_unix_s}, the
// segregation replicates and the fidelity check). What `demcal journal-stats DIR` prints.
//
// Definitions (all times in seconds):
//  - run time of a record: end_unix_s − start_unix_s when it has them, else its wall_time_s;
//  - wall span: the first start to the last end over the records with times;
//  - per (host, rank): busy fraction = the time with at least one run going / wall span, and runs
//    at once = the sum of its run times / wall span (above 1 when a rank runs several side by
//    side, --threads);
//  - critical path: the sum over batches (records sharing batch_unix_s in one journal) of the
//    batch's longest run: the wall time the runs would take with a rank for every run and nothing
//    else to wait for. A timed record without a batch counts as a batch of its own.
// A journal resumed after a stop has the stop inside its span, which lowers the busy fractions.
//
//   JournalStats s;  std::string error;
//   if (!ReadJournalStats("out/study", &s, &error)) fail(error);
//   std::cout << JournalStatsText(s);
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace demcal::workflow {

// One finished run of a journal (times in seconds since the epoch).
struct JournalRun {
  std::string host;
  int rank = 0;
  double start = 0, end = 0, batch = 0, time_s = 0;
  bool timed = false;  // has start and end (host, rank and batch then too)
  int journal = 0;     // which journal (batches of different journals are different batches)
};

// Every run of the journals under `dir`, journal by journal (paths sorted); *journals counts the
// journals read. False with "FILE:LINE: ..." when a journal cannot be read, or none is there.
bool ReadJournalRuns(const std::string& dir, std::vector<JournalRun>* runs, int* journals,
                     std::string* error);

// The length of the union of the intervals [a, b] (the time with at least one of them going).
double CoveredSeconds(std::vector<std::pair<double, double>> intervals);

struct RankUse {
  std::string host;
  int rank = 0;
  int runs = 0;
  double run_time_s = 0;       // sum of its run times
  double busy_fraction = 0;    // of the wall span with at least one of its runs going
  double runs_at_once = 0;     // sum of its run times / wall span
};

struct JournalStats {
  int journals = 0;
  int simulations = 0;         // records (finished runs, failed ones included)
  int untimed = 0;             // records without host, rank and times (older journals)
  double run_time_s = 0;       // sum over every record
  double mean_run_time_s = 0;
  double wall_span_s = 0;
  double runs_at_once = 0;     // run time of the timed records / wall span
  int batches = 0;
  double critical_path_s = 0;
  std::vector<RankUse> ranks;  // by host, then rank
};

// False with "FILE:LINE: ..." when a journal cannot be read; a folder without journals is an
// error too (nothing to report).
bool ReadJournalStats(const std::string& dir, JournalStats* stats, std::string* error);

std::string JournalStatsText(const JournalStats& stats);  // one line per figure, units in labels
nlohmann::ordered_json JournalStatsJson(const JournalStats& stats);

}  // namespace demcal::workflow
