#pragma once
// Fnv1a64: the 64-bit FNV-1a hash (Fowler, Noll, Vo; offset basis 14695981039346656037, prime
// 1099511628211), used for checkpoint checksums, scene fingerprints and the calibration journal's
// study fingerprint. Not cryptographic: it detects corruption (any single changed byte always
// changes the digest, since each step is a bijection of the state; other damage escapes with
// probability 2^-64), not forgery.
//
// Values are fed by their bytes (same build and machine type, like the checkpoint itself);
// Field() takes arithmetic values one by one so structs never contribute padding bytes.
//
// Usage:
//   Fnv1a64 h;
//   h.Bytes(data, size);
//   h.Field(1.5), h.Text("name");
//   uint64_t digest = h.digest();
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/math/vec3.h"

namespace demcal::core {

class Fnv1a64 {
 public:
  void Bytes(const void* data, size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    uint64_t h = hash_;
    for (size_t k = 0; k < size; ++k) h = (h ^ p[k]) * 1099511628211ull;
    hash_ = h;
  }
  template <class T>
  void Field(const T& value) {
    static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>);
    Bytes(&value, sizeof(T));
  }
  void Field(const Vec3& v) { Field(v.x), Field(v.y), Field(v.z); }
  // Length-prefixed, so ("ab", "c") and ("a", "bc") differ.
  void Text(std::string_view s) {
    Field(static_cast<uint64_t>(s.size()));
    Bytes(s.data(), s.size());
  }
  uint64_t digest() const { return hash_; }

 private:
  uint64_t hash_ = 14695981039346656037ull;
};

inline uint64_t Fnv1a64Of(std::string_view bytes) {
  Fnv1a64 h;
  h.Bytes(bytes.data(), bytes.size());
  return h.digest();
}

// The digest of `bytes` as 16 lower-case hex digits (as written into journal headers).
inline std::string Fnv1a64Hex(std::string_view bytes) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(Fnv1a64Of(bytes)));
  return text;
}

}  // namespace demcal::core
