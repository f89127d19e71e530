#include "outputs/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <system_error>

#include "core/io/own_file.h"

namespace demcal::workflow {
namespace {

std::string NowUtc() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// The holder's line from the lock file ("pid 123: demcal simulate, since ..."), or "".
std::string ReadHolder(int fd) {
  char buffer[512];
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  if (n <= 0) return "";
  std::string text(buffer, static_cast<size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\0')) text.pop_back();
  return text;
}

}  // namespace

OutputLock::~OutputLock() { Release(); }

void OutputLock::Release() {
  if (fd_ < 0) return;
  ::flock(fd_, LOCK_UN);
  ::close(fd_);
  fd_ = -1;
}

bool LockOutputDirectory(const std::string& dir, const std::string& command, OutputLock* lock,
                         std::string* error) {
  auto fail = [&](const std::string& what) {
    if (error) *error = what;
    return false;
  };
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fail("cannot create output directory '" + dir + "': " + ec.message());
  if (!std::filesystem::is_directory(dir, ec))
    return fail("--out '" + dir + "' exists and is not a directory");
  lock->Release();
  const std::string path = (std::filesystem::path(dir) / kOutputLockFile).string();
  // The lock file is truncated and rewritten in place, so it is opened without following a link
  // (a link there would lead the pid line into the link's target, or create a file outside
  // --out). No O_EXCL: the file outlives its holder by design, and the flock is the lock.
  std::string open_error;
  const int fd = core::io::OpenOwnFile(path, O_RDWR | O_CREAT, &open_error);
  if (fd < 0) return fail("cannot create the lock file: " + open_error);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    const std::string holder = ReadHolder(fd);
    ::close(fd);
    if (e != EWOULDBLOCK) return fail("cannot lock '" + path + "': " + std::strerror(e));
    return fail("output directory '" + dir + "' is in use by another demcal process (" +
                (holder.empty() ? std::string("holder unknown") : holder) +
                "); wait for it to finish or choose another --out");
  }
  const std::string holder =
      "pid " + std::to_string(::getpid()) + ": " + command + ", since " + NowUtc() + "\n";
  // Informative only: the flock is the lock, so a failed write does not matter.
  [[maybe_unused]] const int truncated = ::ftruncate(fd, 0);
  [[maybe_unused]] const ssize_t written = ::pwrite(fd, holder.data(), holder.size(), 0);
  lock->fd_ = fd;
  return true;
}

}  // namespace demcal::workflow
