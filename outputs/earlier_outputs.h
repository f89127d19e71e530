#pragma once
// What a rejected run does with the outputs an earlier run left in its --out directory. A run
// that refuses its input (exit code 2) must not leave DIR looking like a finished run of that
// input, so the earlier run's files are moved, not deleted, into DIR/previous_run/ (replacing
// an older previous_run/), and the rejection is written beside them (summary.json for simulate,
// rejected.json for experiment). Only files that demcal itself writes are moved (the names and
// prefixes below), never anything else in DIR, and never the calibration journal
// (journal.jsonl), which a corrected study resumes from. The choice is documented in
// docs/cli.md, "Rejected runs".
//
// Thread-safety: call with the directory locked (output_lock.h).
#include <string>
#include <vector>

namespace demcal::workflow {

inline constexpr const char* kPreviousRunDir = "previous_run";

// True if `name` (a file name in DIR, no path) is one of demcal's outputs other than the journal.
bool IsDemcalOutputName(const std::string& name);

// Moves demcal's outputs in `dir` into dir/previous_run/. *moved lists the names moved (empty:
// nothing was there; then no previous_run/ is created and an older one is left as it is).
// Files that are the paths in `keep` (the run's own inputs, e.g. DIR/scene.json given as the
// scene) stay. False with *error if a move failed (the files not yet moved stay in place).
bool SetAsideEarlierOutputs(const std::string& dir, const std::vector<std::string>& keep,
                            std::vector<std::string>* moved, std::string* error);

}  // namespace demcal::workflow
