#include "calibrate/evaluation_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace demcal::calibrate {
namespace {

constexpr const char* kFormat = "demcal-journal/1";

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

std::string RecordLine(const ReplicateRecord& r) {
  nlohmann::json j;
  j["parameters"] = r.parameters;  // shortest round-trip form: reads back bit-identical
  j["replicate"] = r.replicate;
  j["seed"] = r.seed;
  j["status"] = r.status;
  j["value"] = r.ok() ? nlohmann::json(r.value) : nlohmann::json(nullptr);
  j["wall_time_s"] = r.wall_time_s;
  return j.dump() + "\n";
}

bool ParseRecord(const nlohmann::json& j, ReplicateRecord* r) {
  if (!j.is_object() || !j.contains("parameters") || !j.contains("replicate") || !j.contains("seed"))
    return false;
  r->parameters = j.at("parameters").get<std::vector<double>>();
  r->replicate = j.at("replicate").get<int>();
  r->seed = j.at("seed").get<uint64_t>();
  r->status = j.value("status", std::string("ok"));
  r->value = j.at("value").is_number() ? j.at("value").get<double>() : 0.0;
  r->wall_time_s = j.value("wall_time_s", 0.0);
  return r->ok() == j.at("value").is_number();
}

}  // namespace

EvaluationJournal::~EvaluationJournal() {
  if (fd_ >= 0) ::close(fd_);
}

bool EvaluationJournal::Open(const std::string& path, const std::string& fingerprint,
                             std::string* error) {
  path_ = path;
  std::string content;
  {
    std::ifstream in(path, std::ios::binary);
    if (in) content.assign(std::istreambuf_iterator<char>(in), {});
  }
  // A kill during a write leaves a line without its newline: drop it.
  const size_t complete = content.rfind('\n') == std::string::npos ? 0 : content.rfind('\n') + 1;
  content.resize(complete);
  std::istringstream lines(content);
  std::string line;
  bool has_header = false;
  for (int number = 1; std::getline(lines, line); ++number) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    const std::string at = path + ":" + std::to_string(number) + ": ";
    if (!has_header) {
      if (!j.is_object() || j.value("format", "") != kFormat)
        return Fail(error, at + "not a demcal journal (the header must have format \"" + kFormat + "\")");
      if (j.value("study", "") != fingerprint)
        return Fail(error, path + ": this journal belongs to a different study (other model, "
                                  "parameters, fidelity, seed or experiment); use another output "
                                  "directory or delete the journal to start afresh");
      has_header = true;
      continue;
    }
    ReplicateRecord r;
    if (j.is_discarded() || !ParseRecord(j, &r)) return Fail(error, at + "not a journal record");
    records_[{r.parameters, r.replicate}] = r;
  }
  loaded_ = records_.size();
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd_ < 0) return Fail(error, path + ": cannot write: " + std::strerror(errno));
  if (::ftruncate(fd_, static_cast<off_t>(complete)) != 0)
    return Fail(error, path + ": cannot truncate the cut-off last line: " + std::strerror(errno));
  if (!has_header) {
    nlohmann::json header{{"format", kFormat}, {"study", fingerprint}};
    const std::string text = header.dump() + "\n";
    if (::write(fd_, text.data(), text.size()) != static_cast<ssize_t>(text.size()) || ::fsync(fd_) != 0)
      return Fail(error, path + ": cannot write the header: " + std::strerror(errno));
  }
  return true;
}

const ReplicateRecord* EvaluationJournal::Find(const std::vector<double>& parameters, int replicate,
                                               uint64_t seed) const {
  std::lock_guard lock(mutex_);
  const auto it = records_.find({parameters, replicate});
  return it != records_.end() && it->second.seed == seed ? &it->second : nullptr;
}

bool EvaluationJournal::Append(const ReplicateRecord& record, std::string* error) {
  const std::string line = RecordLine(record);
  std::lock_guard lock(mutex_);
  if (fd_ < 0) return Fail(error, "journal not open");
  if (::write(fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size()) || ::fsync(fd_) != 0)
    return Fail(error, path_ + ": cannot append: " + std::strerror(errno));
  records_[{record.parameters, record.replicate}] = record;
  return true;
}

size_t EvaluationJournal::Records() const {
  std::lock_guard lock(mutex_);
  return records_.size();
}

}  // namespace demcal::calibrate
