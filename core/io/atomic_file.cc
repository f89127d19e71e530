#include "core/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace demcal::core::io {
namespace {

// fsync through a fresh descriptor: std::ofstream does not expose its own, and on POSIX fsync
// flushes the file's data whichever descriptor names it.
bool SyncPath(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: the file system cannot sync
  ::close(fd);
  return ok;
}

std::string DirectoryOf(const std::string& path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

}  // namespace

AtomicFile::AtomicFile(std::string path, bool binary)
    : path_(std::move(path)), temporary_(path_ + ".tmp." + std::to_string(::getpid())) {
  // A stale entry at the temporary's name (a crashed run's, or a link planted there) is removed
  // first: unlink removes a link itself, never its target, so the text is never written through
  // a link. rename(2) in Commit likewise replaces a link at NAME with the new file rather than
  // writing into what the link points to.
  std::remove(temporary_.c_str());
  out_.open(temporary_, std::ios::trunc | (binary ? std::ios::binary : std::ios::openmode{}));
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (out_.is_open()) out_.close();
  std::remove(temporary_.c_str());
}

bool AtomicFile::Commit(std::string* error) {
  auto fail = [&](const std::string& reason) {
    if (error) *error = "cannot write '" + path_ + "': " + reason;
    if (out_.is_open()) out_.close();
    std::remove(temporary_.c_str());
    return false;
  };
  if (!out_.is_open()) return fail("cannot create '" + temporary_ + "' (missing directory?)");
  out_.flush();
  if (!out_) return fail("write failed (disk full?)");
  out_.close();
  if (out_.fail()) return fail("write failed on close (disk full?)");
  if (!SyncPath(temporary_, O_RDONLY)) return fail(std::string("fsync: ") + std::strerror(errno));
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
    return fail(std::string("rename: ") + std::strerror(errno));
  committed_ = true;
  SyncPath(DirectoryOf(path_), O_RDONLY | O_DIRECTORY);  // best effort: the rename's durability
  return true;
}

bool WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                         std::string* error, bool binary) {
  AtomicFile file(path, binary);
  if (file.is_open()) write(file.stream());
  return file.Commit(error);
}

}  // namespace demcal::core::io
