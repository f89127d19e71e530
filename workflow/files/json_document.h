#pragma once
// Reading a JSON input file and writing a result file. Reading: syntax errors are reported with
// line and column, and a key that appears twice in one object is an error (nlohmann would
// silently keep the last one, which makes a file with two "seed"s ambiguous). Messages start
// with the file name.
#include <nlohmann/json.hpp>
#include <string>

namespace demcal::workflow {

// Parses `text` read from `source` (used only in messages).
bool ParseJsonText(const std::string& text, const std::string& source, nlohmann::json* out,
                   std::string* error);

// Reads and parses a file; `what` names it in the message ("scene file", "experiment file").
bool ReadJsonFile(const std::string& path, const std::string& what, nlohmann::json* out,
                  std::string* error);

// Writes `value` as indented JSON (invalid UTF-8 replaced); false with a message naming the file.
bool WriteJsonFile(const std::string& path, const nlohmann::ordered_json& value,
                   std::string* error);

}  // namespace demcal::workflow
