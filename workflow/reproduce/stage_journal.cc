#include "workflow/reproduce/stage_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>

#include "core/io/input_file.h"
#include "core/io/own_file.h"
#include "files/input_file.h"

namespace demcal::workflow {
namespace {

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

StageJournal::~StageJournal() {
  if (fd_ >= 0) ::close(fd_);
}

bool StageJournal::Open(const std::string& path, const std::string& fingerprint,
                        std::string* error, bool read_only) {
  path_ = path;
  read_only_ = read_only;
  std::string text;
  // The journal is appended to in place: a link at its name, or a FIFO or device, is refused
  // rather than read and written through. A missing journal is a fresh run's.
  if (!core::io::ReadRegularFile(path, "stage journal", kMaxTableInputBytes,
                                 {.missing_is_empty = true, .refuse_link = true}, &text, error))
    return false;
  // A kill while appending leaves at most one unterminated last line: drop it.
  size_t complete = text.rfind('\n');
  complete = complete == std::string::npos ? 0 : complete + 1;
  text.resize(complete);
  if (!Load(text, fingerprint, error)) return false;
  if (read_only) return true;
  std::string open_error;
  fd_ = core::io::OpenOwnFile(path, O_WRONLY | O_CREAT | O_APPEND, &open_error);
  if (fd_ < 0) return Fail(error, "cannot write the stage journal: " + open_error);
  if (::ftruncate(fd_, static_cast<off_t>(complete)) != 0)
    return Fail(error, path + ": cannot drop the cut-off last line: " + std::strerror(errno));
  if (complete == 0) {
    nlohmann::json header{{"format", kStageJournalFormat}, {"workflow", fingerprint}};
    return AppendLine(header.dump() + "\n", error);
  }
  return true;
}

bool StageJournal::Load(const std::string& text, const std::string& fingerprint,
                        std::string* error) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string at = path_ + ":" + std::to_string(number) + ": ";
    nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object()) return Fail(error, at + "not a JSON object");
    if (number == 1) {
      if (j.value("format", "") != kStageJournalFormat)
        return Fail(error, at + "not a stage journal (the header must have format \"" +
                               kStageJournalFormat + "\")");
      if (j.value("workflow", "") != fingerprint)
        return Fail(error, path_ + ": this journal belongs to another workflow file or fidelity "
                                   "(--quick or not); use another --out or delete the journal to "
                                   "start afresh");
      continue;
    }
    if (!j.contains("key") || !j["key"].is_string() || j["key"].get<std::string>().empty() ||
        !j.contains("result"))
      return Fail(error, at + "a record needs a non-empty string \"key\" and a \"result\"");
    if (!records_.emplace(j["key"].get<std::string>(), j["result"]).second)
      return Fail(error, at + "key '" + j["key"].get<std::string>() +
                             "' recorded twice; the journal has been edited or mixed");
  }
  return true;
}

const nlohmann::json* StageJournal::Find(const std::string& key) const {
  std::lock_guard lock(mutex_);
  auto it = records_.find(key);
  return it == records_.end() ? nullptr : &it->second;
}

bool StageJournal::Record(const std::string& key, const nlohmann::json& result,
                          std::string* error) {
  std::lock_guard lock(mutex_);
  if (records_.count(key)) return Fail(error, path_ + ": key '" + key + "' already recorded");
  nlohmann::json record{{"key", key}, {"result", result}};
  const std::string line =
      record.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  if (!read_only_ && !AppendLine(line, error)) return false;
  records_.emplace(key, result);
  return true;
}

size_t StageJournal::size() const {
  std::lock_guard lock(mutex_);
  return records_.size();
}

bool StageJournal::AppendLine(const std::string& line, std::string* error) {
  if (fd_ < 0) return Fail(error, path_ + ": journal not open");
  if (::write(fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size()) ||
      ::fsync(fd_) != 0)
    return Fail(error, path_ + ": cannot append: " + std::strerror(errno));
  return true;
}

}  // namespace demcal::workflow
