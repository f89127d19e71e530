#pragma once
// ReadInputFile: the one way demcal reads a user's input file (scene, experiment, study,
// dataset, measurement table, workflow) into memory: core::io::ReadRegularFile, which refuses
// what is not a regular file (a directory, /dev/zero, a FIFO) and anything larger than a cap
// before reading a byte. Messages start with the path.
//
//   std::string text, error;
//   if (!ReadInputFile(path, "scene file", kMaxJsonInputBytes, &text, &error)) report(error);
//
// Thread-safety: a free function, no shared state.
#include <cstddef>
#include <string>

namespace demcal::workflow {

// 64 MiB: about 400,000 explicitly listed particles in a scene, far above any bundled input,
// and small enough that the parsed document (about 10x the text) fits in memory.
inline constexpr size_t kMaxJsonInputBytes = size_t{64} << 20;
// 64 MiB for CSV tables and journals too (a measurement table has tens of rows).
inline constexpr size_t kMaxTableInputBytes = size_t{64} << 20;

// Reads the whole file; `what` names it in messages ("scene file").
bool ReadInputFile(const std::string& path, const std::string& what, size_t max_bytes,
                   std::string* text, std::string* error);

}  // namespace demcal::workflow
