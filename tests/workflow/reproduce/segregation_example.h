#pragma once
// examples/segregation_paper.json as the JSON the workflow's stages edit (experiment_edit.h).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "workflow/reproduce/experiment_edit.h"
#include "workflow/test_paths.h"

namespace demcal::workflow::testing_support {

inline nlohmann::ordered_json SegregationExample() {
  nlohmann::ordered_json e;
  std::string error;
  REQUIRE(ReadExperimentJson(
      (demcal::testing::RepoRoot() / "examples/segregation_paper.json").string(), &e, &error));
  return e;
}

}  // namespace demcal::workflow::testing_support
