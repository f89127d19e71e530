#include "core/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "core/io/own_file.h"

namespace demcal::core::io {
namespace {

std::string Mebibytes(size_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

bool Fail(const std::string& path, const std::string& what, const std::string& problem,
          std::string* error) {
  if (error) *error = path + ": cannot read the " + what + ": " + problem;
  return false;
}

// What a non-regular, non-directory file is, for the message.
std::string KindOf(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a device, FIFO or socket";
}

}  // namespace

bool ReadRegularFile(const std::string& path, const std::string& what, size_t max_bytes,
                     const ReadOptions& options, std::string* text, std::string* error) {
  if (path.empty()) return Fail("(empty path)", what, "no file name given", error);
  // Open first, then fstat the descriptor, so the checks and the read see the same file.
  // O_NONBLOCK keeps a FIFO from blocking the open; it is refused right after.
  const int flags = O_RDONLY | O_CLOEXEC | O_NONBLOCK | (options.refuse_link ? O_NOFOLLOW : 0);
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) {
    const int e = errno;
    if (e == ENOENT && options.missing_is_empty) {
      text->clear();
      return true;
    }
    if (e == ELOOP && options.refuse_link) {
      if (error) *error = LinkRefusedMessage(path);
      return false;
    }
    return Fail(path, what, std::strerror(e), error);
  }
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
    return Fail(path, what, "not a regular file but " + KindOf(st.st_mode), error);
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

}  // namespace demcal::core::io
