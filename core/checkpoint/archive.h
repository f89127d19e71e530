#pragma once
// Archive: a minimal binary archive for checkpoints. One class serves both directions so each
// state-holding class writes a single `template <class A> void Serialize(A&)` listing its
// members once (no reader/writer twins). Only trivially copyable values and vectors of them are
// stored, raw, in the machine's byte order (a checkpoint is for restarting on the same build).
// Reading never allocates more than the bytes left could hold, so a damaged length cannot
// exhaust memory; what was read is then validated by its owner (core/checkpoint/checkpoint.cc).
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace demcal::core {

class Archive {
 public:
  static Archive ForWriting() { return Archive(true, {}); }
  static Archive ForReading(std::string bytes) { return Archive(false, std::move(bytes)); }

  bool writing() const { return writing_; }
  bool ok() const { return ok_; }  // false after reading past the end
  // Bytes not yet read (reading); a complete payload leaves none.
  size_t remaining() const { return writing_ ? 0 : bytes_.size() - offset_; }
  const std::string& bytes() const { return bytes_; }

  template <class T>
  void Value(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    Raw(&v, sizeof(T));
  }
  template <class T>
  void Vector(std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    uint64_t n = v.size();
    Value(n);
    if (!writing_) {
      if (!ok_ || n > (bytes_.size() - offset_) / (sizeof(T) ? sizeof(T) : 1)) {
        ok_ = false;
        return;
      }
      v.resize(n);
    }
    Raw(v.data(), n * sizeof(T));
  }
  void String(std::string& s) {
    std::vector<char> chars(s.begin(), s.end());
    Vector(chars);
    if (!writing_) s.assign(chars.begin(), chars.end());
  }

 private:
  Archive(bool writing, std::string bytes) : writing_(writing), bytes_(std::move(bytes)) {}
  void Raw(void* data, size_t n) {
    if (writing_) {
      bytes_.append(static_cast<const char*>(data), n);
    } else if (ok_ && offset_ + n <= bytes_.size()) {
      if (n) std::memcpy(data, bytes_.data() + offset_, n);
      offset_ += n;
    } else {
      ok_ = false;
    }
  }

  bool writing_ = false;
  bool ok_ = true;
  std::string bytes_;
  size_t offset_ = 0;
};

}  // namespace demcal::core
