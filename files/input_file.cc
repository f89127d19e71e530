#include "files/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace demcal::workflow {
namespace {

std::string Mebibytes(size_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

bool Fail(const std::string& path, const std::string& what, const std::string& problem,
          std::string* error) {
  if (error) *error = path + ": cannot read the " + what + ": " + problem;
  return false;
}

}  // namespace

bool ReadInputFile(const std::string& path, const std::string& what, size_t max_bytes,
                   std::string* text, std::string* error) {
  if (path.empty()) return Fail("(empty path)", what, "no file name given", error);
  // Open first, then fstat the descriptor, so the checks and the read see the same file.
  // O_NONBLOCK keeps a FIFO from blocking the open; it is refused right after.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return Fail(path, what, std::strerror(errno), error);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int e = errno;
    ::close(fd);
    return Fail(path, what, std::strerror(e), error);
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    return Fail(path, what, "it is a directory, not a file", error);
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    return Fail(path, what, "not a regular file (a device, FIFO or socket)", error);
  }
  if (static_cast<uint64_t>(st.st_size) > max_bytes) {
    ::close(fd);
    return Fail(path, what,
                "it holds " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                    Mebibytes(max_bytes),
                error);
  }
  std::string bytes;
  bytes.reserve(static_cast<size_t>(st.st_size));
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int e = errno;
      ::close(fd);
      return Fail(path, what, std::strerror(e), error);
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<size_t>(n));
    // The file may grow while it is read: the cap holds for what is read, too.
    if (bytes.size() > max_bytes) {
      ::close(fd);
      return Fail(path, what, "it grew beyond the limit of " + Mebibytes(max_bytes), error);
    }
  }
  ::close(fd);
  *text = std::move(bytes);
  return true;
}

}  // namespace demcal::workflow
