#pragma once
// Test helper: the repository root, so tests that read examples/, datasets/ and tests/data/ run
// from any working directory. The build defines DEMCAL_TEST_SOURCE_DIR (tests/CMakeLists.txt);
// without it, the root is found from this header's own path (<root>/tests/workflow/).
#include <filesystem>

namespace demcal::testing {

inline std::filesystem::path RepoRoot() {
#ifdef DEMCAL_TEST_SOURCE_DIR  // absolute: __FILE__ is relative when ccache's base_dir is set
  return std::filesystem::path(DEMCAL_TEST_SOURCE_DIR);
#endif
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
}

}  // namespace demcal::testing
