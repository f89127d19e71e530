#pragma once
// Scene JSON parsing: turns a "demcal-scene/1" document into a SceneFile and validates it before
// anything runs. Errors are one line naming the file, the JSON path of the offending field and
// what is allowed, e.g.
//   scenes/a.json: field 'materials[0].poisson_ratio' = 0.7 is outside the allowed range (-1, 0.5)
//   scenes/a.json: unknown key 'species[1].diamter_m' (did you mean 'diameter_m'?); allowed ...
//   scenes/a.json: field 'species[0].material' = 'steal' names no material (defined: glass)
// The JSON layer checks structure (unknown keys, missing fields, types, references by name,
// ranges of values whose core field has a different shape); core::Scene::IsValid then checks
// every physical range, with field names that match the JSON paths.
//
// Usage:
//   SceneFile file;  std::string error;
//   if (!LoadSceneFile("examples/pour_box.json", &file, &error)) { std::cerr << error; }
#include <nlohmann/json.hpp>
#include <string>

#include "files/scene_file.h"

namespace demcal::workflow {

// Parses a document already read from `source` (used only in messages).
bool ParseSceneJson(const nlohmann::json& document, const std::string& source, SceneFile* out,
                    std::string* error);
// Parses JSON text: syntax errors report line and column; duplicate keys are rejected.
bool ParseSceneText(const std::string& text, const std::string& source, SceneFile* out,
                    std::string* error);
// Reads and parses a file.
bool LoadSceneFile(const std::string& path, SceneFile* out, std::string* error);

}  // namespace demcal::workflow
