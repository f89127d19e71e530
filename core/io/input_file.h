#pragma once
// ReadRegularFile: the one way demcal reads a file into memory, for the user's inputs (scene,
// study, measurement table, workflow) and for its own files in --out (journals). It refuses what
// is not a regular file (a directory, /dev/zero, a FIFO) and anything larger than a cap before
// reading a byte, so a wrong path ends at once with a message that says what the path is,
// instead of hanging on a FIFO or reading until memory runs out. Messages start with the path.
//
//   std::string text, error;
//   if (!ReadRegularFile(path, "scene file", 64 << 20, {}, &text, &error)) report(error);
//
// Thread-safety: a free function, no shared state.
#include <cstddef>
#include <string>

namespace demcal::core::io {

struct ReadOptions {
  // A missing file reads as empty (a journal that a fresh run is about to create).
  bool missing_is_empty = false;
  // A symbolic link as the last path component is refused (demcal's own lock and journal files:
  // a link planted there must not lead demcal to read, and later write, another file).
  bool refuse_link = false;
};

// Reads the whole file; `what` names it in messages ("scene file").
bool ReadRegularFile(const std::string& path, const std::string& what, size_t max_bytes,
                     const ReadOptions& options, std::string* text, std::string* error);

}  // namespace demcal::core::io
