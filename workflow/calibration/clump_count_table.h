#pragma once
// The clump-count loop's table (paper section 2.4): one row per sphere count n with how well the
// continuous parameters calibrated at n fit the targets, and the verdict over all rows — the
// count chosen and the counts the data cannot tell apart. Pure: testable without a simulation.
#include <string>
#include <vector>

#include "calibrate/calibration.h"

namespace demcal::workflow {

struct StudyFile;

struct ClumpCountRow {
  int count = 0;
  calibrate::Termination termination = calibrate::Termination::kFailed;
  double cost = 0;            // Σ standardised residual² at the best candidate (NaN: none)
  bool within_noise = false;  // the calibration at n ended with a match
  // Some candidate at n agrees with the data jointly within noise (TrialResult::WithinNoise or
  // Inconclusive): the data do not exclude n. `agreeing_noise` is the largest simulation noise
  // (sem / u) of the most precise such candidate (NaN: none agrees).
  bool agrees = false;
  double agreeing_noise = 0;
  double wall_per_run_s = 0;  // mean wall time of one replicate run (cost per heap)
  int runs = 0;
};
ClumpCountRow ClumpCountRowOf(int count, const calibrate::CalibrationSummary& s, double wall_per_run_s);

struct ClumpCountVerdict {
  int chosen = -1;                  // the smallest count that matches (−1: none)
  std::vector<int> matching;        // counts whose calibration matched
  std::vector<int> not_told_apart;  // counts the data do not exclude, when more than one
  std::string note;                 // the verdict in words
};
// Counts that agree with the data are not told apart by these targets; among them the smallest
// confirmed by simulations at least as precise as the measurement is chosen. A smaller count
// that agrees only inconclusively is named, never silently dropped.
ClumpCountVerdict JudgeClumpCounts(const std::vector<ClumpCountRow>& rows);

// clump_count.json and clump_count.csv into dir; false with the error.
bool WriteClumpCountOutputs(const std::string& dir, const StudyFile& study, const std::vector<ClumpCountRow>& rows,
                            const ClumpCountVerdict& verdict, std::string* error);

}  // namespace demcal::workflow
