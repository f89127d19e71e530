#include "calibrate/evaluation_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>

#include "calibrate/observable_registry.h"
#include "calibrate/run_status.h"
#include "core/io/input_file.h"
#include "core/io/own_file.h"
#include "objectives/common/replicates.h"

namespace demcal::calibrate {
namespace {

// The header's study fingerprint is FNV-1a 64 (core/math/fnv1a.h). Journals of earlier versions
// hold fingerprints computed otherwise, which can never match: they are refused by their version,
// with what to do, rather than as "a different study".
constexpr int kVersion = 3;
constexpr const char* kFormatPrefix = "demcal-journal/";
const std::string kFormat = kFormatPrefix + std::to_string(kVersion);

// The version of a "demcal-journal/N" header, or 0 when it is not one.
int FormatVersion(const std::string& format) {
  if (format.rfind(kFormatPrefix, 0) != 0) return 0;
  const std::string digits = format.substr(std::strlen(kFormatPrefix));
  if (digits.empty() || digits.size() > 6 ||
      digits.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  return std::stoi(digits);
}

// 256 MiB: about a million records of a few hundred bytes; a study of a thousand evaluations of
// ten replicates writes about 3 MiB. The cap keeps /dev/zero or a runaway file from filling memory.
constexpr size_t kMaxJournalBytes = size_t{256} << 20;
// A record is ~200 bytes; a megabyte line is not one of ours (and a cheap guard before parsing).
constexpr size_t kMaxLineBytes = 1 << 20;
// A record nests 2 deep; the parser recurses, so a hostile deep line must be refused before it.
constexpr int kMaxDepth = 8;

int NestingDepth(const std::string& text) {
  int depth = 0, deepest = 0;
  bool quoted = false;
  for (size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (quoted) {
      if (c == '\\') ++k;
      else if (c == '"') quoted = false;
    } else if (c == '"') quoted = true;
    else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    else if (c == ']' || c == '}') --depth;
  }
  return deepest;
}

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

std::string RecordLine(const ReplicateRecord& r) {
  nlohmann::json j;
  if (!r.group.empty()) j["group"] = r.group;
  j["parameters"] = r.parameters;  // shortest round-trip form: reads back bit-identical
  j["replicate"] = r.replicate;
  j["seed"] = r.seed;
  j["status"] = r.status;
  if (!r.values.empty() || !r.group.empty())
    j["values"] = r.ok() ? nlohmann::json(r.values) : nlohmann::json(nullptr);
  else
    j["value"] = r.ok() ? nlohmann::json(r.value) : nlohmann::json(nullptr);
  j["wall_time_s"] = r.wall_time_s;
  if (r.start_unix_s > 0) {
    j["host"] = r.host;
    j["rank"] = r.rank;
    j["start_unix_s"] = r.start_unix_s;
    j["end_unix_s"] = r.end_unix_s;
    j["batch_unix_s"] = r.batch_unix_s;
  }
  return j.dump() + "\n";
}

bool Finite(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

// A value of observable `name` must lie in its physical range (registered observables) and be
// finite; a journal line that breaks this was not written by demcal.
std::string CheckValue(const std::string& name, double v) {
  const ObservableInfo* info = FindObservable(name);
  // A value under a name demcal does not measure would be found as a replicate run yet give
  // its target nothing: the record is refused rather than counted as done.
  if (!info) {
    std::string names;
    for (const std::string& n : ObservableNames()) names += (names.empty() ? "" : ", ") + n;
    return name + ": not an observable demcal measures (" + names + ")";
  }
  if (!info->Contains(v))
    return name + " = " + std::to_string(v) + " outside " + info->RangeText();
  return "";
}

// The optional host, rank and times of a record ("" when absent or sound).
std::string ParseWhereAndWhen(const nlohmann::json& j, ReplicateRecord* r) {
  if (j.contains("host")) {
    if (!j.at("host").is_string() || j.at("host").get<std::string>().size() > 255)
      return "host: must be a string of at most 255 characters";
    r->host = j.at("host").get<std::string>();
  }
  if (j.contains("rank")) {
    if (!j.at("rank").is_number_unsigned() || j.at("rank").get<uint64_t>() > 10000000)
      return "rank: must be a whole number in [0, 10000000]";
    r->rank = j.at("rank").get<int>();
  }
  for (auto [key, field] : {std::pair{"start_unix_s", &r->start_unix_s},
                            std::pair{"end_unix_s", &r->end_unix_s},
                            std::pair{"batch_unix_s", &r->batch_unix_s}}) {
    if (!j.contains(key)) continue;
    if (!Finite(j.at(key)) || j.at(key).get<double>() < 0)
      return std::string(key) + ": must be a finite number of seconds >= 0";
    *field = j.at(key).get<double>();
  }
  if (r->end_unix_s < r->start_unix_s) return "end_unix_s: must not be before start_unix_s";
  return "";
}

// "" when the record is sound, else what is wrong with it.
std::string ParseRecord(const nlohmann::json& j, size_t parameter_count, ReplicateRecord* r) {
  if (!j.is_object()) return "not a JSON object";
  for (const char* key : {"parameters", "replicate", "seed", "status"})
    if (!j.contains(key)) return std::string("missing '") + key + "'";
  const nlohmann::json& p = j.at("parameters");
  if (!p.is_array() || p.empty()) return "parameters: must be a non-empty array of numbers";
  for (const nlohmann::json& v : p)
    if (!Finite(v)) return "parameters: must be finite numbers";
  if (parameter_count > 0 && p.size() != parameter_count)
    return "parameters: " + std::to_string(p.size()) + " values, the study has " +
           std::to_string(parameter_count);
  r->parameters = p.get<std::vector<double>>();
  if (!j.at("replicate").is_number_unsigned() || j.at("replicate").get<uint64_t>() > 1000000)
    return "replicate: must be a whole number in [0, 1000000]";
  r->replicate = j.at("replicate").get<int>();
  if (!j.at("seed").is_number_unsigned()) return "seed: must be a whole number >= 0";
  r->seed = j.at("seed").get<uint64_t>();
  if (!j.at("status").is_string() || j.at("status").get<std::string>().empty())
    return "status: must be a non-empty string";
  r->status = j.at("status").get<std::string>();
  if (!IsRunStatus(r->status)) {
    std::string names;
    for (const std::string& n : RunStatusNames()) names += (names.empty() ? "" : ", ") + n;
    return "status: '" + r->status + "' is not a status demcal writes (" + names + ")";
  }
  if (j.contains("group") && !j.at("group").is_string()) return "group: must be a string";
  r->group = j.value("group", std::string());
  if (j.contains("wall_time_s") && !(Finite(j.at("wall_time_s")) && j.at("wall_time_s").get<double>() >= 0))
    return "wall_time_s: must be a finite number >= 0";
  r->wall_time_s = j.value("wall_time_s", 0.0);
  if (std::string why = ParseWhereAndWhen(j, r); !why.empty()) return why;
  const bool has_values = j.contains("values"), has_value = j.contains("value");
  if (has_values == has_value) return "needs exactly one of 'value' or 'values'";
  const nlohmann::json& v = has_values ? j.at("values") : j.at("value");
  if (!r->ok()) return v.is_null() ? "" : "a failed run carries no value";
  if (has_value) {
    if (!Finite(v)) return "value: must be a finite number for status ok";
    r->value = v.get<double>();
    return "";
  }
  if (!v.is_object() || v.empty()) return "values: must be an object of observable -> number";
  for (const auto& [name, x] : v.items()) {
    if (!Finite(x)) return "values." + name + ": must be a finite number";
    if (std::string why = CheckValue(name, x.get<double>()); !why.empty()) return "values." + why;
    r->values[name] = x.get<double>();
  }
  return "";
}

// What the run gave; where, when and how long it took are not part of it.
bool SameRecord(const ReplicateRecord& a, const ReplicateRecord& b) {
  return a.seed == b.seed && a.status == b.status && a.value == b.value && a.values == b.values;
}

}  // namespace

EvaluationJournal::~EvaluationJournal() {
  if (fd_ >= 0) ::close(fd_);
}

bool EvaluationJournal::Open(const std::string& path, const std::string& fingerprint,
                             std::string* error, size_t parameter_count, bool read_only) {
  path_ = path;
  read_only_ = read_only;
  std::string content;
  // The journal is appended to in place: a link at its name, or a FIFO or device, is refused
  // rather than read and written through. A missing journal is a fresh run's.
  io_error_ = false;
  if (!core::io::ReadRegularFile(path, "journal", kMaxJournalBytes,
                                 {.missing_is_empty = true, .refuse_link = true}, &content, error))
    return false;
  // A kill during a write leaves a line without its newline: drop it.
  const size_t complete = content.rfind('\n') == std::string::npos ? 0 : content.rfind('\n') + 1;
  content.resize(complete);
  std::istringstream lines(content);
  std::string line;
  bool has_header = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (line.size() > kMaxLineBytes || NestingDepth(line) > kMaxDepth)
      return Fail(error, path + ":" + std::to_string(number) + ": not a journal record (longer "
                         "than 1 MiB or nested deeper than 8)");
    nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    const std::string at = path + ":" + std::to_string(number) + ": ";
    if (!has_header) {
      const std::string format = j.is_object() ? j.value("format", "") : "";
      if (const int version = FormatVersion(format); version != 0 && version != kVersion) {
        const std::string by = version < kVersion ? "an older" : "a newer";
        return Fail(error, path + " was written by " + by + " demcal (" + format +
                               "); move it away or use a new --out to start afresh");
      }
      if (format != kFormat)
        return Fail(error, at + "not a demcal journal (the header must have format \"" + kFormat + "\")");
      if (j.value("study", "") != fingerprint)
        return Fail(error, path + ": this journal belongs to a different study (other model, "
                                  "parameters, fidelity, seed or experiment); use another output "
                                  "directory or delete the journal to start afresh");
      has_header = true;
      continue;
    }
    ReplicateRecord r;
    if (j.is_discarded()) return Fail(error, at + "not JSON (a journal line is one JSON record)");
    if (std::string why = ParseRecord(j, parameter_count, &r); !why.empty())
      return Fail(error, at + why);
    if (const uint64_t expected = objectives::ReplicateSeed(expected_base_seed_, r.replicate);
        check_seeds_ && r.seed != expected)
      return Fail(error, at + "seed: " + std::to_string(r.seed) + " is not the seed of replicate " +
                             std::to_string(r.replicate) + " in this study (" +
                             std::to_string(expected) + "); the journal has been edited or mixed");
    const auto [it, inserted] = records_.try_emplace({r.group, r.parameters, r.replicate}, r);
    if (!inserted && !SameRecord(it->second, r))
      return Fail(error, at + "a second record of the same run (group, parameters, replicate) "
                              "with other content; the journal has been edited or mixed");
  }
  loaded_ = records_.size();
  if (read_only) return true;
  std::string open_error;
  fd_ = core::io::OpenOwnFile(path, O_WRONLY | O_CREAT | O_APPEND, &open_error);
  io_error_ = true;  // from here on, a failure is the file system's
  if (fd_ < 0) return Fail(error, "cannot write the journal: " + open_error);
  if (::ftruncate(fd_, static_cast<off_t>(complete)) != 0)
    return Fail(error, path + ": cannot truncate the cut-off last line: " + std::strerror(errno));
  if (!has_header) {
    nlohmann::json header{{"format", kFormat}, {"study", fingerprint}};
    if (!WriteWhole(header.dump() + "\n", error)) return false;
  }
  io_error_ = false;
  return true;
}

const ReplicateRecord* EvaluationJournal::Find(const std::vector<double>& parameters, int replicate,
                                               uint64_t seed) const {
  return Find("", parameters, replicate, seed);
}

const ReplicateRecord* EvaluationJournal::Find(const std::string& group,
                                               const std::vector<double>& parameters,
                                               int replicate, uint64_t seed) const {
  std::lock_guard lock(mutex_);
  const auto it = records_.find({group, parameters, replicate});
  return it != records_.end() && it->second.seed == seed ? &it->second : nullptr;
}

// One whole line or nothing: a write cut short (a full disk, a file size limit) is truncated
// back, so the file never holds half a record that a later line would run into.
bool EvaluationJournal::WriteWhole(const std::string& line, std::string* error) {
  const off_t before = ::lseek(fd_, 0, SEEK_END);
  size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n > 0) {
      done += static_cast<size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      std::string message = path_ + ": cannot write: " + std::strerror(n < 0 ? errno : ENOSPC);
      if (before >= 0 && ::ftruncate(fd_, before) != 0)
        message += "; the last line is left cut short (dropped when the journal is next opened)";
      io_error_ = true;
      return Fail(error, message);
    }
  }
  if (::fsync(fd_) != 0) {
    io_error_ = true;
    return Fail(error, path_ + ": cannot write: " + std::strerror(errno));
  }
  return true;
}

bool EvaluationJournal::Append(const ReplicateRecord& record, std::string* error) {
  const std::string line = RecordLine(record);
  std::lock_guard lock(mutex_);
  if (read_only_) {
    records_[{record.group, record.parameters, record.replicate}] = record;
    return true;
  }
  if (fd_ < 0) return Fail(error, "journal not open");
  if (!write_error_.empty()) return Fail(error, write_error_);
  if (!WriteWhole(line, &write_error_)) return Fail(error, write_error_);
  records_[{record.group, record.parameters, record.replicate}] = record;
  return true;
}

size_t EvaluationJournal::Records() const {
  std::lock_guard lock(mutex_);
  return records_.size();
}

}  // namespace demcal::calibrate
