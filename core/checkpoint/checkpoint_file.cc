#include "core/checkpoint/checkpoint_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/math/fnv1a.h"
#include "core/io/atomic_file.h"

namespace demcal::core {
namespace {

constexpr char kMagic[8] = {'d', 'e', 'm', 'c', 'a', 'l', 'C', 'K'};
constexpr uint32_t kByteOrderMark = 0x01020304;
// Format 4 and older began with the length-prefixed string "demcal-checkpoint/N".
constexpr char kOldMagic[] = "demcal-checkpoint/";

template <class T>
T Load(const std::string& bytes, size_t offset) {
  T v;
  std::memcpy(&v, bytes.data() + offset, sizeof(T));
  return v;
}
template <class T>
void Store(std::string& bytes, const T& v) {
  bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

bool Fail(const std::string& why, std::string* error) {
  if (error) *error = why;
  return false;
}

// The header checks; `file_size` is the whole file's size. Sets *payload_size.
bool CheckHeader(const std::string& header, uint64_t file_size, uint64_t* payload_size,
                 std::string* error) {
  if (header.size() < kCheckpointHeaderBytes)
    return Fail("truncated: " + std::to_string(file_size) + " bytes, shorter than the " +
                    std::to_string(kCheckpointHeaderBytes) + "-byte header",
                error);
  if (std::memcmp(header.data(), kMagic, sizeof(kMagic)) != 0) {
    if (header.find(kOldMagic) == 8)
      return Fail("format '" + header.substr(8, 19) + "' of an older demcal; this build reads "
                  "format " + std::to_string(kCheckpointFormatVersion) + " (rerun from the scene)",
                  error);
    return Fail("not a demcal checkpoint (no 'demcalCK' magic at the start)", error);
  }
  if (Load<uint32_t>(header, 12) != kByteOrderMark)
    return Fail("written on a machine of another byte order", error);
  const uint32_t version = Load<uint32_t>(header, 8);
  if (version != kCheckpointFormatVersion)
    return Fail("format version " + std::to_string(version) + "; this build reads version " +
                    std::to_string(kCheckpointFormatVersion) +
                    " (written by another demcal build: resume it with that build, or rerun "
                    "from the scene)",
                error);
  *payload_size = Load<uint64_t>(header, 16);
  const uint64_t have = file_size - kCheckpointHeaderBytes;
  if (have < *payload_size)
    return Fail("truncated: the header announces " + std::to_string(*payload_size) +
                    " payload bytes, the file holds " + std::to_string(have),
                error);
  if (have > *payload_size)
    return Fail(std::to_string(have - *payload_size) +
                    " unexpected bytes after the end of the checkpoint (appended to?)",
                error);
  return true;
}

}  // namespace

std::string FrameCheckpoint(const std::string& payload) {
  std::string bytes(kMagic, sizeof(kMagic));
  Store(bytes, kCheckpointFormatVersion);
  Store(bytes, kByteOrderMark);
  Store(bytes, static_cast<uint64_t>(payload.size()));
  Store(bytes, Fnv1a64Of(payload));
  return bytes + payload;
}

bool WriteCheckpointFile(const std::string& path, const std::string& payload, std::string* error) {
  const std::string bytes = FrameCheckpoint(payload);
  return io::WriteFileAtomically(
      path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); },
      error, /*binary=*/true);
}

bool UnframeCheckpoint(const std::string& file_bytes, std::string* payload, std::string* error) {
  uint64_t size = 0;
  if (!CheckHeader(file_bytes.substr(0, kCheckpointHeaderBytes), file_bytes.size(), &size, error))
    return false;
  *payload = file_bytes.substr(kCheckpointHeaderBytes);
  const uint64_t stored = Load<uint64_t>(file_bytes, 24);
  if (Fnv1a64Of(*payload) != stored)
    return Fail("checksum mismatch: the payload was damaged or edited after it was written", error);
  return true;
}

bool ReadCheckpointFile(const std::string& path, std::string* payload, std::string* error) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return Fail(std::string("cannot read the file: ") + std::strerror(errno), error);
  if (S_ISDIR(st.st_mode)) return Fail("cannot read the file: it is a directory", error);
  if (!S_ISREG(st.st_mode)) return Fail("not a regular file (a device, FIFO or socket)", error);
  std::ifstream in(path, std::ios::binary);
  std::string header(kCheckpointHeaderBytes, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<size_t>(in.gcount()));
  uint64_t size = 0;
  if (!in.is_open()) return Fail("cannot read the file", error);
  if (!CheckHeader(header, static_cast<uint64_t>(st.st_size), &size, error)) return false;
  std::string bytes = header;
  bytes.resize(kCheckpointHeaderBytes + size);
  in.read(bytes.data() + kCheckpointHeaderBytes, static_cast<std::streamsize>(size));
  if (static_cast<uint64_t>(in.gcount()) != size)
    return Fail("cannot read the file (it changed while being read?)", error);
  return UnframeCheckpoint(bytes, payload, error);
}

}  // namespace demcal::core
