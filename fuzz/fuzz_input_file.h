#pragma once
// The readers that take a path get the fuzzer's bytes through a file: WriteFuzzInput writes
// them to `name` inside a directory of this process's own (/tmp/demcal_fuzz_<pid>/), so that
// relative paths in the input resolve to nothing and parallel fuzzing jobs never share a file.
// Returns the file's path, or "" if it could not be written (the input is then skipped).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

namespace demcal::fuzz {

inline std::string WriteFuzzInput(const std::string& name, const uint8_t* data, size_t size) {
  static const std::string dir = [] {
    const std::string d = "/tmp/demcal_fuzz_" + std::to_string(::getpid());
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::string path = dir + "/" + name;
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return "";
  const bool written = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && written ? path : "";
}

}  // namespace demcal::fuzz
