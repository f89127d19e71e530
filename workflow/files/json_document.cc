#include "workflow/files/json_document.h"

#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "objectives/report/text_file.h"

namespace demcal::workflow {

namespace {

using nlohmann::json;

// Records the first key repeated within one object.
class DuplicateKeyCheck {
 public:
  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        keys_.emplace_back();
        break;
      case json::parse_event_t::object_end:
        if (!keys_.empty()) keys_.pop_back();
        break;
      case json::parse_event_t::key:
        if (!keys_.empty() && !keys_.back().insert(parsed.get<std::string>()).second &&
            duplicate_.empty())
          duplicate_ = parsed.get<std::string>();
        break;
      default:
        break;
    }
    return true;
  }
  const std::string& duplicate() const { return duplicate_; }

 private:
  std::vector<std::set<std::string>> keys_;
  std::string duplicate_;
};

}  // namespace

bool ParseJsonText(const std::string& text, const std::string& source, json* out,
                   std::string* error) {
  DuplicateKeyCheck duplicates;
  try {
    *out = json::parse(text, std::ref(duplicates));
  } catch (const json::parse_error& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ...".
    std::string what = e.what();
    const size_t start = what.find("] ");
    if (error)
      *error = source +
               ": invalid JSON: " + (start == std::string::npos ? what : what.substr(start + 2));
    return false;
  }
  if (!duplicates.duplicate().empty()) {
    if (error)
      *error = source + ": key '" + duplicates.duplicate() +
               "' appears twice in one object; JSON keys must be unique";
    return false;
  }
  return true;
}

bool ReadJsonFile(const std::string& path, const std::string& what, json* out,
                  std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = path + ": cannot open the " + what;
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return ParseJsonText(text.str(), path, out, error);
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
