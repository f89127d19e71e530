#pragma once
// OutputLock: one demcal process per output directory. LockOutputDirectory takes an exclusive
// flock(2) on DIR/.demcal.lock and writes the holder into it (pid, command, start time); a second
// process asking for the same DIR is refused with a message naming the holder, before it writes
// anything. The kernel releases the lock when the holder exits, even after kill -9, so a stale
// lock file never blocks a later run (the file itself stays; its content is only informative).
//
// Thread-safety: one OutputLock per process and directory; not for threads of one process.
//
// Usage (first thing a command does with its --out, before any file is written there):
//   OutputLock lock;
//   if (!LockOutputDirectory(out_dir, "demcal simulate", &lock, &error)) return refuse(error);
#include <string>

namespace demcal::workflow {

class OutputLock {
 public:
  OutputLock() = default;
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  bool held() const { return fd_ >= 0; }
  void Release();

 private:
  friend bool LockOutputDirectory(const std::string&, const std::string&, OutputLock*,
                                  std::string*);
  int fd_ = -1;
};

inline constexpr const char* kOutputLockFile = ".demcal.lock";

// Creates `dir` if needed and locks it for this process; `command` names the holder in the
// lock file ("demcal calibrate"). False with *error = "DIR is in use by another demcal process
// (pid P: COMMAND, since TIME); wait for it to finish or choose another --out", or why the lock
// could not be taken.
bool LockOutputDirectory(const std::string& dir, const std::string& command, OutputLock* lock,
                         std::string* error);

}  // namespace demcal::workflow
