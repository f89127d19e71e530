#pragma once
// WallTimeModel: the wall time a job would take on N ranks, predicted from the run times measured
// in its journals (journal_stats.h), for `demcal journal-stats DIR --model-ranks 8,64,512`.
//
// Model (docs/scale.md, "Wall-time model"):
//  - Batches run in sequence, in the order they started: a batch is the runs that share
//    batch_unix_s (a calibration's evaluator batch, or the batches of the calibrations that
//    reproduce runs together, which the farm starts as one; reproduce's segregation
//    replicates), whichever journals hold them; a run without a batch is a batch of its own.
//  - Inside a batch the farm hands the runs out from a queue to the first free slot (list
//    scheduling, farm.h); the queue order is the order in which the runs started. Each run
//    keeps its measured time at any rank count: a slot is a core of its own, and nothing else
//    slows a run down (no contention for memory bandwidth or a shared core).
//  - Slots: under mpirun rank 0 only manages, so N ranks give N − 1 slots (one run each,
//    --threads 0); N = 1 is the run without mpirun with one run at a time (--threads 1).
//  - What is not a run (the optimiser, stage bookkeeping, the gaps between batches while the
//    next is prepared) takes the measured time between the batches, the same at every N.
// The prediction is of the journals' wall span (first start to last end), the part of a
// command's wall time that the farm can shorten; reading the inputs before the first run and
// writing the report after the last are outside it.
//
//   std::vector<JournalRun> runs;  int journals;
//   ReadJournalRuns(dir, &runs, &journals, &error);
//   WallTimeModel m = ModelWallTime(runs, {8, 64, 512});
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "workflow/journal_stats/journal_stats.h"

namespace demcal::workflow {

struct WallTimePrediction {
  int ranks = 0;
  int slots = 0;  // runs at once: max(1, ranks − 1)
  double wall_span_s = 0;
};

struct WallTimeModel {
  int runs = 0;                  // timed runs (the others have no place in a batch)
  int batches = 0;
  double measured_span_s = 0;    // first start to last end, as run
  double between_batches_s = 0;  // of the span with no batch going
  double run_time_s = 0;         // sum of the timed runs
  std::vector<WallTimePrediction> predictions;
};

// The latest time a slot frees when `times` (queue order) go to `slots` slots, each run to the
// first slot free (ties: the lowest slot).
double ListScheduleMakespan(const std::vector<double>& times, int slots);

// Predictions at each of `ranks` (each ≥ 1) from the timed runs of `runs`.
WallTimeModel ModelWallTime(const std::vector<JournalRun>& runs, const std::vector<int>& ranks);

std::string WallTimeModelText(const WallTimeModel& model);  // one line per figure
nlohmann::ordered_json WallTimeModelJson(const WallTimeModel& model);

}  // namespace demcal::workflow
