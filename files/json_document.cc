#include "files/json_document.h"

#include <set>
#include <vector>

#include "objectives/report/text_file.h"
#include "files/input_file.h"

namespace demcal::workflow {

namespace {

using nlohmann::json;

// Builds the document from SAX events without recursion, tracking the JSON path of the value
// being read (for messages), the nesting depth and the keys of every open object.
class CheckedBuilder {
 public:
  explicit CheckedBuilder(json* root) : root_(root) {}

  bool null() { return Put(json(nullptr)); }
  bool boolean(bool v) { return Put(json(v)); }
  bool number_integer(json::number_integer_t v) { return Put(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return Put(json(v)); }
  bool number_float(json::number_float_t v, const std::string& /*text*/) { return Put(json(v)); }
  bool string(json::string_t& v) { return Put(json(std::move(v))); }
  bool binary(json::binary_t& /*v*/) { return Fail("binary values are not JSON text"); }
  bool start_object(size_t /*size*/) { return Open(json::object()); }
  bool start_array(size_t /*size*/) { return Open(json::array()); }
  bool end_object() { return Close(); }
  bool end_array() { return Close(); }
  bool key(json::string_t& k) {
    Frame& f = frames_.back();
    f.key = k;  // also names the duplicate in the message's path
    if (!f.keys.insert(k).second)
      return Fail("key '" + k + "' appears twice in one object; JSON keys must be unique");
    return true;
  }
  bool parse_error(size_t /*position*/, const std::string& /*token*/,
                   const json::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ...".
    const std::string what = e.what();
    if (e.id == 406) {  // out_of_range.406: "number overflow parsing '1e999'"
      const size_t quote = what.find('\'');
      const std::string number = quote == std::string::npos ? "" : what.substr(quote);
      message_ = "number " + number +
                 " is out of range: a number must be finite, at most 1.8e308 in magnitude";
      with_path_ = true;
      return false;
    }
    const size_t start = what.find("] ");
    message_ = "invalid JSON: " + (start == std::string::npos ? what : what.substr(start + 2));
    with_path_ = false;
    return false;
  }

  // The message of the first problem, with the JSON path where it helps.
  std::string Message() const {
    if (!with_path_) return message_;
    const std::string path = Path();
    return (path.empty() ? std::string("(document)") : path) + ": " + message_;
  }
  bool failed() const { return !message_.empty(); }

 private:
  struct Frame {
    json* value;
    std::set<std::string> keys;  // objects only
    std::string key;             // objects: the key being read
    size_t index = 0;            // arrays: the element being read
  };

  // The path of the value being read: "materials[1].name".
  std::string Path() const {
    std::string path;
    for (const Frame& f : frames_) {
      if (f.value->is_object()) {
        if (f.key.empty()) continue;
        path += (path.empty() ? "" : ".") + f.key;
      } else {
        path += "[" + std::to_string(f.index) + "]";
      }
    }
    return path;
  }

  // Places `v` where the next value goes; returns where it now lives.
  json* Insert(json v) {
    if (frames_.empty()) {
      *root_ = std::move(v);
      return root_;
    }
    Frame& f = frames_.back();
    if (f.value->is_object()) return &((*f.value)[f.key] = std::move(v));
    f.value->push_back(std::move(v));
    return &f.value->back();
  }
  void Advance() {
    if (frames_.empty()) return;
    Frame& f = frames_.back();
    if (f.value->is_array()) ++f.index;
  }
  bool Put(json v) {
    Insert(std::move(v));
    Advance();
    return true;
  }
  bool Open(json v) {
    if (static_cast<int>(frames_.size()) >= kMaxJsonDepth)
      return Fail("nesting deeper than " + std::to_string(kMaxJsonDepth) +
                  " levels; demcal files nest a few levels only");
    json* placed = Insert(std::move(v));
    frames_.push_back({placed, {}, {}, 0});
    return true;
  }
  bool Close() {
    frames_.pop_back();
    Advance();
    return true;
  }
  bool Fail(std::string message) {
    message_ = std::move(message);
    with_path_ = true;
    return false;
  }

  json* root_;
  std::vector<Frame> frames_;
  std::string message_;
  bool with_path_ = false;
};

}  // namespace

bool ParseJsonText(const std::string& text, const std::string& source, json* out,
                   std::string* error) {
  json document;
  CheckedBuilder builder(&document);
  bool parsed = false;
  try {
    parsed = json::sax_parse(text, &builder);
  } catch (const json::exception& e) {
    // sax_parse reports through parse_error(); this is a safety net for anything else.
    if (error) *error = source + ": invalid JSON: " + e.what();
    return false;
  }
  if (!parsed || builder.failed()) {
    if (error)
      *error = source + ": " + (builder.failed() ? builder.Message() : "invalid JSON");
    return false;
  }
  *out = std::move(document);
  return true;
}

bool ReadJsonFile(const std::string& path, const std::string& what, json* out,
                  std::string* error) {
  std::string text;
  return ReadInputFile(path, what, kMaxJsonInputBytes, &text, error) &&
         ParseJsonText(text, path, out, error);
}

bool WriteJsonFile(const std::string& path, const nlohmann::ordered_json& value,
                   std::string* error) {
  return objectives::WriteTextFile(
      path,
      [&](std::ostream& out) {
        out << value.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
      },
      error);
}

}  // namespace demcal::workflow
