#pragma once
// Test helper: examples/pour_box.json as a JSON document, the valid scene the scene-file tests
// edit one key at a time.
#include <fstream>
#include <nlohmann/json.hpp>

#include "workflow/test_paths.h"

namespace demcal::testing {

inline nlohmann::json PourBoxDocument() {
  return nlohmann::json::parse(std::ifstream((RepoRoot() / "examples" / "pour_box.json").string()));
}

}  // namespace demcal::testing
