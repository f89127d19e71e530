#pragma once
// JsonFields: a checked reader for one JSON object of an input file. It knows the JSON path of
// the object ("materials[1]"), rejects keys it was not told about (with a did-you-mean hint),
// and reads typed fields, recording the first problem as a message that names the field's path,
// what was expected and, for ranges, the allowed interval. Once a problem is recorded every
// later call is a no-op, so a parser can read a whole object and test ok() once.
//
// Only apps/ parses files; the readers fill core option structs and never throw.
//
// Usage:
//   JsonStatus status;
//   JsonFields f(json, "materials[0]", {"name", "poisson_ratio"}, &status);
//   f.String("name", &m.name, kRequired);
//   f.Number("poisson_ratio", &m.poisson_ratio, kRequired, Range::Open(-1, 0.5));
//   if (!status.ok()) report(status.message());
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/math/vec3.h"
#include "objectives/common/input_limits.h"

namespace demcal::workflow {

// The first error met while reading a document.
class JsonStatus {
 public:
  bool ok() const { return ok_; }
  const std::string& message() const { return message_; }
  void Fail(std::string message) {
    if (ok_) message_ = std::move(message);
    ok_ = false;
  }

 private:
  bool ok_ = true;
  std::string message_;
};

// An allowed interval for a number; open ends exclude the bound.
struct Range {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  const char* unit = "";

  static Range Closed(double lo, double hi, const char* unit = "") {
    return {lo, hi, false, false, unit};
  }
  static Range LeftOpen(double lo, double hi, const char* unit = "") {
    return {lo, hi, true, false, unit};
  }
  static Range Open(double lo, double hi, const char* unit = "") {
    return {lo, hi, true, true, unit};
  }
  // A limit of the input-limits table (objectives/common/input_limits.h).
  static Range Of(const objectives::limits::Limit& limit, const char* unit = "") {
    return {limit.lo, limit.hi, limit.lo_open, limit.hi_open, unit};
  }
  static Range Any() { return {}; }
  bool Contains(double v) const;
  std::string Describe() const;  // e.g. "(0, 1]"
};

enum Presence { kOptional, kRequired };

// "array[3]"-style and "object.key"-style path pieces.
std::string JoinPath(const std::string& parent, const std::string& key);
std::string IndexPath(const std::string& parent, size_t index);
// A number in messages: 6 significant digits ("1e+06", "0.25").
std::string FormatNumber(double v);
// "number", "string", "array", ... as a user would say it.
std::string JsonTypeName(const nlohmann::json& value);

class JsonFields {
 public:
  // Records a type error if `object` is not an object, and an error for the first key not in
  // `allowed`.
  JsonFields(const nlohmann::json& object, std::string path, std::vector<std::string> allowed,
             JsonStatus* status);
  // The reader keeps a reference to `object`: a temporary would dangle.
  JsonFields(nlohmann::json&& object, std::string path, std::vector<std::string> allowed,
             JsonStatus* status) = delete;

  bool ok() const { return status_->ok(); }
  bool Has(const std::string& key) const;
  std::string PathOf(const std::string& key) const { return JoinPath(path_, key); }
  const std::string& path() const { return path_; }
  void Fail(const std::string& key, const std::string& problem);

  // Each reader leaves *out untouched when the key is absent (and kOptional) or on error.
  void Number(const std::string& key, double* out, Presence presence, Range range = Range::Any());
  void Integer(const std::string& key, int64_t* out, Presence presence, Range range = Range::Any());
  void Unsigned(const std::string& key, uint64_t* out, Presence presence);
  // An array of integers, each within `range`; a bad element is named by its index
  // ("counts[2]"), so a value such as 4294967297 is refused, never narrowed to fit.
  void Integers(const std::string& key, std::vector<int64_t>* out, Presence presence,
                Range range = Range::Any());
  void Bool(const std::string& key, bool* out, Presence presence);
  // Non-empty string; with `choices`, one of them.
  void String(const std::string& key, std::string* out, Presence presence,
              const std::vector<std::string>& choices = {});
  void Vector(const std::string& key, core::Vec3* out, Presence presence);
  // An array of exactly `size` numbers.
  void Numbers(const std::string& key, size_t size, std::vector<double>* out, Presence presence);
  // The value of an object- or array-valued key, or nullptr if absent or of the wrong type.
  const nlohmann::json* Object(const std::string& key, Presence presence);
  const nlohmann::json* Array(const std::string& key, Presence presence);
  // The raw value if present and no error so far; records "missing" when required and absent.
  const nlohmann::json* Value(const std::string& key, Presence presence);

 private:
  void TypeError(const std::string& key, const std::string& expected, const nlohmann::json& got);

  const nlohmann::json& object_;
  std::string path_;
  std::vector<std::string> allowed_;
  JsonStatus* status_;
};

}  // namespace demcal::workflow
