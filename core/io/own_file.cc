#include "core/io/own_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace demcal::core::io {

std::string LinkRefusedMessage(const std::string& path) {
  return path + " is a symbolic link; demcal does not follow links for its lock/journal files";
}

int OpenOwnFile(const std::string& path, int flags, std::string* error) {
  // O_NOFOLLOW fails with ELOOP on a link as the last component, a dangling one included (with
  // O_CREAT too), so nothing is created at the link's target. O_NONBLOCK keeps a FIFO from
  // blocking the open; it is refused just below. It has no effect on a regular file.
  const int fd = ::open(path.c_str(), flags | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644);
  if (fd < 0) {
    const int e = errno;
    if (error) *error = e == ELOOP ? LinkRefusedMessage(path) : path + ": " + std::strerror(e);
    return -1;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    if (error) *error = path + ": not a regular file (a directory, device, FIFO or socket)";
    return -1;
  }
  return fd;
}

}  // namespace demcal::core::io
