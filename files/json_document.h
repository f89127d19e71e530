#pragma once
// Reading a JSON input file and writing a result file. Every JSON input goes through one
// discipline, before any field is looked at:
//   - the file must be a regular file of at most kMaxJsonInputBytes (input_file.h);
//   - nesting deeper than kMaxJsonDepth is refused while parsing (the parser is an iterative SAX
//     reader, so a 100,000-deep array gives a message, not a stack overflow);
//   - syntax errors are reported with line and column; a number that overflows a double (1e999)
//     with its JSON path;
//   - a key that appears twice in one object is an error (nlohmann would silently keep the last
//     one, which makes a file with two "seed"s ambiguous).
// Messages start with the file name: "scene.json: materials[0].density_kg_m3: ...".
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace demcal::workflow {

// 64 levels: the deepest bundled input nests 6; a hand-written file never needs more, and the
// readers and nlohmann's dump() recurse once per level.
inline constexpr int kMaxJsonDepth = 64;

// Parses `text` read from `source` (used only in messages).
bool ParseJsonText(const std::string& text, const std::string& source, nlohmann::json* out,
                   std::string* error);

// Reads and parses a file; `what` names it in the message ("scene file", "experiment file").
bool ReadJsonFile(const std::string& path, const std::string& what, nlohmann::json* out,
                  std::string* error);

// JSON has no NaN or infinity: a figure that is not finite (not determined, a failed run) is
// written as null.
inline nlohmann::json NumOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

// Writes `value` as indented JSON (invalid UTF-8 replaced) atomically (text_file.h); false with
// a message naming the file.
bool WriteJsonFile(const std::string& path, const nlohmann::ordered_json& value,
                   std::string* error);

}  // namespace demcal::workflow
