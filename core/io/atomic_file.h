#pragma once
// AtomicFile: an output file that appears complete or not at all. The text goes to a temporary
// file in the same directory ("NAME.tmp.PID"); Commit() flushes it, fsyncs it, renames it over
// NAME and fsyncs the directory. A process killed at any byte leaves either the old complete
// file or the new complete one (plus, at worst, a stray NAME.tmp.PID), never a half-written NAME.
// Destroying an uncommitted AtomicFile removes its temporary.
//
// Thread-safety: one object per thread; two processes writing the same NAME each use their own
// temporary and the last rename wins (outputs/output_lock.h keeps them apart).
//
// Usage:
//   AtomicFile file(path);
//   file.stream() << "a,b\n";
//   if (!file.Commit(&error)) report(error);
#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace demcal::core::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path, bool binary = false);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // False if the temporary could not be created (then Commit fails with the reason).
  bool is_open() const { return out_.is_open(); }
  std::ostream& stream() { return out_; }
  // Makes the new content the file's; false with "cannot write 'PATH': reason" in *error.
  bool Commit(std::string* error);
  const std::string& path() const { return path_; }

 private:
  std::string path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

// The whole write in one call: `write` fills the stream; false (and no change to `path`) when
// the file could not be created or written.
bool WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                         std::string* error, bool binary = false);

}  // namespace demcal::core::io
