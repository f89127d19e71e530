#pragma once
// OpenOwnFile: opens a file demcal keeps in its --out directory and writes in place (the lock
// file, the journals) without following a symbolic link. Those files are written through an
// open descriptor (truncated, appended to), so a link planted at their name would make demcal
// destroy the link's target or create a file outside --out; a link is refused instead, as is
// anything that is not a regular file. Files written whole go through AtomicFile
// (atomic_file.h), whose rename replaces a link rather than writing through it.
//
//   const int fd = OpenOwnFile(path, O_WRONLY | O_CREAT | O_APPEND, &error);
//   if (fd < 0) report(error);
//
// Thread-safety: free functions, no shared state.
#include <string>

namespace demcal::core::io {

// "PATH is a symbolic link; demcal does not follow links for its lock/journal files".
std::string LinkRefusedMessage(const std::string& path);

// open(2) with `flags` plus O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK and mode 0644; the descriptor,
// or -1 with a message naming the path in *error (a link, a non-regular file, or errno's text).
int OpenOwnFile(const std::string& path, int flags, std::string* error);

}  // namespace demcal::core::io
