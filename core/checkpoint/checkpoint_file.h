#pragma once
// Checkpoint framing: the envelope around a checkpoint's payload (the Archive bytes of
// Simulation::SerializeState), so that a file is verified before any of it is believed.
//
// Layout (32-byte header, then the payload; integers in the machine's byte order):
//   [0, 8)    magic "demcalCK"
//   [8, 12)   format version (uint32, kCheckpointFormatVersion)
//   [12, 16)  byte-order mark 0x01020304 (a file from a machine of the other byte order is refused)
//   [16, 24)  payload length in bytes (uint64)
//   [24, 32)  FNV-1a 64 digest of the payload (uint64, core/math/fnv1a.h)
//   [32, ...) payload
// Reading checks, in this order, each refusal naming the check: regular file; header present;
// magic (and names the older format "demcal-checkpoint/4" when it sees one); byte order;
// version; length (a truncated file and bytes appended after the payload are told apart);
// checksum. The payload itself is then checked by the Simulation (fingerprint, every index).
//
// Writing goes through core::io::AtomicFile (temporary, fsync, rename): a kill at any byte
// leaves the old complete checkpoint or the new one.
#include <cstdint>
#include <string>

namespace demcal::core {

inline constexpr uint32_t kCheckpointFormatVersion = 8;
inline constexpr size_t kCheckpointHeaderBytes = 32;

// The whole file for `payload`.
std::string FrameCheckpoint(const std::string& payload);
// Writes FrameCheckpoint(payload) to `path` atomically; false with "cannot write ..." in *error.
bool WriteCheckpointFile(const std::string& path, const std::string& payload, std::string* error);
// Verifies the envelope of a whole file's bytes and extracts the payload; false with the failed
// check in *error (no file name: the caller adds it).
bool UnframeCheckpoint(const std::string& file_bytes, std::string* payload, std::string* error);
// Reads `path` (a regular file; the header is checked before the rest is read, so a huge or
// endless file is refused early) and unframes it.
bool ReadCheckpointFile(const std::string& path, std::string* payload, std::string* error);

}  // namespace demcal::core
