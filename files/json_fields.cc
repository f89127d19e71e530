#include "files/json_fields.h"

#include <algorithm>
#include <cmath>

#include "core/math/number_text.h"

namespace demcal::workflow {
namespace {

// Levenshtein distance, for "did you mean" hints on misspelt keys.
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A short rendering of a JSON value for messages.
std::string Brief(const nlohmann::json& v) {
  std::string s = v.dump();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

bool IsIntegral(const nlohmann::json& v) {
  if (v.is_number_integer()) return true;
  if (!v.is_number_float()) return false;
  const double d = v.get<double>();
  return std::floor(d) == d && std::abs(d) < 9.0e15;
}

// The value as an int64_t when it is an integer that fits one exactly (1e4 counts, 2.5 and
// 2^63 do not).
bool ToInt64(const nlohmann::json& v, int64_t* out) {
  if (!IsIntegral(v) || (v.is_number_unsigned() && v.get<uint64_t>() > INT64_MAX)) return false;
  *out = v.is_number_float() ? static_cast<int64_t>(v.get<double>()) : v.get<int64_t>();
  return true;
}

}  // namespace

std::string FormatNumber(double v) { return core::NumberText(v); }

bool Range::Contains(double v) const {
  return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

// Readable bounds: "(0, 1]", "> 0", ">= 0 s", never "-inf" or a 300-digit number.
std::string Range::Describe() const {
  const bool no_lo = lo <= -1e300, no_hi = hi >= 1e300;
  std::string s;
  if (no_lo && no_hi)
    s = "any number of magnitude <= 1e300";
  else if (no_hi)
    s = (lo_open ? "> " : ">= ") + FormatNumber(lo);
  else if (no_lo)
    s = (hi_open ? "< " : "<= ") + FormatNumber(hi);
  else
    s = (lo_open ? "(" : "[") + FormatNumber(lo) + ", " + FormatNumber(hi) + (hi_open ? ")" : "]");
  if (*unit) s += std::string(" ") + unit;
  return s;
}

std::string JoinPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string IndexPath(const std::string& parent, size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string JsonTypeName(const nlohmann::json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "boolean";
  if (v.is_number()) return "number";
  if (v.is_string()) return "string";
  if (v.is_array()) return "array";
  if (v.is_object()) return "object";
  return "value";
}

JsonFields::JsonFields(const nlohmann::json& object, std::string path,
                       std::vector<std::string> allowed, JsonStatus* status)
    : object_(object), path_(std::move(path)), allowed_(std::move(allowed)), status_(status) {
  if (!status_->ok()) return;
  if (!object_.is_object()) {
    status_->Fail("field '" + (path_.empty() ? std::string("(document)") : path_) +
                  "' must be an object, got " + JsonTypeName(object_) + " " + Brief(object_));
    return;
  }
  for (const auto& item : object_.items()) {
    const std::string& key = item.key();
    if (std::find(allowed_.begin(), allowed_.end(), key) != allowed_.end()) continue;
    std::string closest;
    size_t best = 3;  // suggest only near misses
    for (const std::string& a : allowed_) {
      const size_t d = EditDistance(key, a);
      if (d < best) best = d, closest = a;
    }
    std::string message = "unknown key '" + PathOf(key) + "'";
    if (!closest.empty()) message += " (did you mean '" + closest + "'?)";
    message += "; allowed keys here:";
    for (size_t k = 0; k < allowed_.size(); ++k) message += (k ? ", " : " ") + allowed_[k];
    status_->Fail(message);
    return;
  }
}

bool JsonFields::Has(const std::string& key) const {
  return object_.is_object() && object_.contains(key);
}

void JsonFields::Fail(const std::string& key, const std::string& problem) {
  status_->Fail("field '" + PathOf(key) + "' " + problem);
}

const nlohmann::json* JsonFields::Value(const std::string& key, Presence presence) {
  if (!ok()) return nullptr;
  if (!Has(key)) {
    if (presence == kRequired) status_->Fail("missing required field '" + PathOf(key) + "'");
    return nullptr;
  }
  return &object_.at(key);
}

void JsonFields::TypeError(const std::string& key, const std::string& expected,
                           const nlohmann::json& got) {
  Fail(key, "must be " + expected + ", got " + JsonTypeName(got) + " " + Brief(got));
}

void JsonFields::Number(const std::string& key, double* out, Presence presence, Range range) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  if (!v->is_number()) return TypeError(key, "a number", *v);
  const double d = v->get<double>();
  if (!range.Contains(d))
    return Fail(key, "= " + FormatNumber(d) + " is outside the allowed range " + range.Describe());
  *out = d;
}

void JsonFields::Integer(const std::string& key, int64_t* out, Presence presence, Range range) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  int64_t i = 0;
  if (!ToInt64(*v, &i)) return TypeError(key, "an integer", *v);
  if (!range.Contains(static_cast<double>(i)))
    return Fail(key,
                "= " + std::to_string(i) + " is outside the allowed range " + range.Describe());
  *out = i;
}

void JsonFields::Unsigned(const std::string& key, uint64_t* out, Presence presence) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  if (!IsIntegral(*v)) return TypeError(key, "a non-negative integer", *v);
  if (v->is_number_float()) {
    const double d = v->get<double>();
    if (d < 0) return TypeError(key, "a non-negative integer", *v);
    *out = static_cast<uint64_t>(d);
    return;
  }
  if (v->is_number_integer() && !v->is_number_unsigned() && v->get<int64_t>() < 0)
    return TypeError(key, "a non-negative integer", *v);
  *out = v->get<uint64_t>();
}

void JsonFields::Integers(const std::string& key, std::vector<int64_t>* out, Presence presence,
                          Range range) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  if (!v->is_array()) return TypeError(key, "an array of integers", *v);
  std::vector<int64_t> values;
  for (size_t k = 0; k < v->size(); ++k) {
    const std::string at = IndexPath(key, k);
    int64_t i = 0;
    if (!ToInt64((*v)[k], &i)) return TypeError(at, "an integer", (*v)[k]);
    if (!range.Contains(static_cast<double>(i)))
      return Fail(at, "= " + std::to_string(i) + " is outside the allowed range " + range.Describe());
    values.push_back(i);
  }
  *out = std::move(values);
}

void JsonFields::Bool(const std::string& key, bool* out, Presence presence) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  if (!v->is_boolean()) return TypeError(key, "true or false", *v);
  *out = v->get<bool>();
}

void JsonFields::String(const std::string& key, std::string* out, Presence presence,
                        const std::vector<std::string>& choices) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  if (!v->is_string() || v->get_ref<const std::string&>().empty())
    return TypeError(key, "a non-empty string", *v);
  const std::string& s = v->get_ref<const std::string&>();
  if (!choices.empty() && std::find(choices.begin(), choices.end(), s) == choices.end()) {
    std::string allowed;
    for (size_t k = 0; k < choices.size(); ++k) allowed += (k ? "|" : "") + choices[k];
    return Fail(key, "= '" + s + "' is not one of " + allowed);
  }
  *out = s;
}

void JsonFields::Numbers(const std::string& key, size_t size, std::vector<double>* out,
                         Presence presence) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return;
  const std::string expected = "an array of " + std::to_string(size) + " numbers";
  if (!v->is_array() || v->size() != size) return TypeError(key, expected, *v);
  std::vector<double> values;
  for (const nlohmann::json& e : *v) {
    if (!e.is_number()) return TypeError(key, expected, *v);
    values.push_back(e.get<double>());
  }
  *out = std::move(values);
}

void JsonFields::Vector(const std::string& key, core::Vec3* out, Presence presence) {
  std::vector<double> values;
  Numbers(key, 3, &values, presence);
  if (values.size() == 3) *out = {values[0], values[1], values[2]};
}

const nlohmann::json* JsonFields::Object(const std::string& key, Presence presence) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return nullptr;
  if (!v->is_object()) {
    TypeError(key, "an object", *v);
    return nullptr;
  }
  return v;
}

const nlohmann::json* JsonFields::Array(const std::string& key, Presence presence) {
  const nlohmann::json* v = Value(key, presence);
  if (!v) return nullptr;
  if (!v->is_array()) {
    TypeError(key, "an array", *v);
    return nullptr;
  }
  return v;
}

}  // namespace demcal::workflow
