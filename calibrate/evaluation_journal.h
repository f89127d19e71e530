#pragma once
// EvaluationJournal: every finished replicate run of a calibration, appended to a JSON-lines file
// as it completes (one line, flushed and fsync'ed), so a calibration killed at any moment resumes
// without losing or repeating finished work: the optimisers are deterministic, so a resumed study
// asks for the same candidates again and finds them here (exact match on the parameter values
// and the replicate's seed).
//
// File: the first line is a header {"format": "demcal-journal/3", "study": <fingerprint>}; then
// one record per replicate run: {"group": g, "parameters": [...], "replicate": r, "seed": s,
// "status": "ok", "values": {"angle_deg": x, ...}, "wall_time_s": t} (single-observable studies
// write "value": x instead of "values"). The group names the experiment run a record belongs to
// (an experiment file under a condition: one heap feeds every target that reads it). A line cut
// short by a kill is dropped on reopening. A journal of another study (a different fingerprint)
// is refused, never mixed in; so is one of another format version ("written by an older demcal
// (demcal-journal/2); move it away or use a new --out to start afresh"). Every record is checked
// on loading: types, finite numbers, the parameter count, values inside their observable's
// physical range, observables demcal knows, a status from RunStatusNames(), the seed the study
// gives the replicate (ExpectSeeds); a bad line is an error "journal.jsonl:LINE: ...", and a
// second record of the same run with other content is an error, never a silent overwrite.
//
//   EvaluationJournal journal;
//   if (!journal.Open(dir + "/journal.jsonl", fingerprint, &error)) ...;
//   if (const ReplicateRecord* done = journal.Find(values, r, seed)) use(*done);
//   else journal.Append(record, &error);
//
// A read-only journal (ranks of an MPI farm other than the manager) loads the file but never
// writes it: Append only adds to the records in memory, so every rank finds the same runs.
//
// Thread-safety: Find and Append may be called from several threads (replicates side by side).
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

namespace demcal::calibrate {

struct ReplicateRecord {
  std::vector<double> parameters;  // SI values, in the parameter space's order
  int replicate = 0;
  uint64_t seed = 0;
  std::string status = "ok";       // "ok", or why the run gave no value
  double value = 0;                // the observable (meaningful when status == "ok")
  double wall_time_s = 0;
  std::string group;                     // the experiment run ("" for single-observable studies)
  std::map<std::string, double> values;  // observable -> value (multi-observable runs)
  // Where and when it ran (0 / "": not recorded; never part of the run's identity).
  std::string host;
  int rank = 0;
  double start_unix_s = 0;
  double end_unix_s = 0;
  double batch_unix_s = 0;
  bool ok() const { return status == "ok"; }
};

class EvaluationJournal {
 public:
  EvaluationJournal() = default;
  ~EvaluationJournal();
  EvaluationJournal(const EvaluationJournal&) = delete;
  EvaluationJournal& operator=(const EvaluationJournal&) = delete;

  // Opens (creating it if absent) and loads the journal; false with a message naming the file
  // if it cannot be read or written, or belongs to another study.
  // parameter_count > 0: every record must have that many parameters.
  // read_only: load, never write (see above).
  bool Open(const std::string& path, const std::string& fingerprint, std::string* error,
            size_t parameter_count = 0, bool read_only = false);
  // Before Open: every record's seed must be objectives::ReplicateSeed(base_seed, replicate),
  // the seed the evaluator asks for; another is refused on loading, naming the line (a record
  // never found again would be run anew, and the journal would then hold two of one run).
  void ExpectSeeds(uint64_t base_seed) { expected_base_seed_ = base_seed, check_seeds_ = true; }
  // After a false Open or Append: the failure was reading or writing the file (exit code 4),
  // not its content (exit code 2).
  bool io_error() const { return io_error_; }

  // The record of this candidate's replicate, or nullptr. The pointer stays valid.
  const ReplicateRecord* Find(const std::vector<double>& parameters, int replicate,
                              uint64_t seed) const;
  const ReplicateRecord* Find(const std::string& group, const std::vector<double>& parameters,
                              int replicate, uint64_t seed) const;
  // Writes one record, flushed and fsync'ed. A write that fails (a full disk) is cut back to
  // the last whole record, and every later Append fails too: a run must stop rather than go on
  // unjournalled.
  bool Append(const ReplicateRecord& record, std::string* error);

  size_t LoadedRecords() const { return loaded_; }  // records found on opening
  size_t Records() const;
  const std::string& path() const { return path_; }

 private:
  bool WriteWhole(const std::string& line, std::string* error);
  using Key = std::tuple<std::string, std::vector<double>, int>;
  std::string path_;
  int fd_ = -1;
  bool read_only_ = false;
  size_t loaded_ = 0;
  bool check_seeds_ = false, io_error_ = false;
  uint64_t expected_base_seed_ = 0;
  std::string write_error_;  // the first failed Append's message; later ones repeat it
  mutable std::mutex mutex_;
  std::map<Key, ReplicateRecord> records_;
};

}  // namespace demcal::calibrate
