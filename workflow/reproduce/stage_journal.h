#pragma once
// StageJournal: what the stages of `demcal reproduce` have finished, as JSON lines in
// DIR/stages.jsonl, so a run killed at any moment (kill -9 included) and started again with the
// same command skips every finished stage and every finished replicate run of an unfinished one.
// (Inside a calibration stage, demcal calibrate's own journal keeps its replicate runs.)
//
// File: line 1 a header {"format": "demcal-stage-journal/1", "workflow": <fingerprint>}; then one
// record per finished piece of work, {"key": "species/BP", "result": {...}}, appended, flushed
// and fsync'ed when it finishes. Keys are "<stage>" for a finished stage and
// "<stage>/<item>" for a finished part of one (a replicate run). On reopening, a last line cut
// short by a kill is dropped; any other bad line is an error naming the file and line; a
// journal with another fingerprint (another workflow file, or --quick against the default
// fidelity) is refused, never mixed in; a key recorded twice is an error.
//
//   StageJournal journal;
//   if (!journal.Open(dir + "/stages.jsonl", fingerprint, &error)) ...;
//   if (const nlohmann::json* done = journal.Find("cohesion")) use(*done);
//   else journal.Record("cohesion", result, &error);
//
// Thread-safety: Find and Record may be called from several threads.
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

namespace demcal::workflow {

inline constexpr const char* kStageJournalFormat = "demcal-stage-journal/1";

class StageJournal {
 public:
  StageJournal() = default;
  ~StageJournal();
  StageJournal(const StageJournal&) = delete;
  StageJournal& operator=(const StageJournal&) = delete;

  // Opens (creating if absent) and loads; false with a message naming the file. With
  // `read_only` (the workers of an MPI farm, which run the same stages as the rank that writes)
  // the file is only read, a missing one is empty, and Record keeps records in memory.
  bool Open(const std::string& path, const std::string& fingerprint, std::string* error,
            bool read_only = false);
  // The result recorded under `key`, or nullptr. The pointer stays valid until the journal dies.
  const nlohmann::json* Find(const std::string& key) const;
  // Appends (and fsyncs) a record; false if the key is already recorded or the write fails.
  bool Record(const std::string& key, const nlohmann::json& result, std::string* error);
  size_t size() const;
  const std::string& path() const { return path_; }

 private:
  bool Load(const std::string& text, const std::string& fingerprint, std::string* error);
  bool AppendLine(const std::string& line, std::string* error);

  std::string path_;
  int fd_ = -1;
  bool read_only_ = false;
  std::map<std::string, nlohmann::json> records_;
  mutable std::mutex mutex_;
};

}  // namespace demcal::workflow
