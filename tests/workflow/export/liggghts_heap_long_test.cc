// [long] An exported heap reproduces in LIGGGHTS: bench/compare_export_heap.sh with no rolling
// friction (the laws both codes share exactly) and CHECK=1, 8 replicates per code of the quick
// aor heap; the mean angles must agree within 3 combined standard errors (docs/export.md:
// 6.93 ± 0.24° and 7.35 ± 0.40° at 16). About a minute on one core. Skipped without liggghts.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/workflow/test_paths.h"

TEST_CASE("export: a cohesionless heap without rolling friction reproduces in LIGGGHTS",
          "[long][.][export]") {
  if (std::system("command -v liggghts > /dev/null 2>&1") != 0) {
    WARN("liggghts is not installed (scripts/install_deps.sh installs it): skipped");
    return;
  }
  namespace fs = std::filesystem;
  // The build folder holds this test binary in tests/.
  const fs::path build = fs::canonical("/proc/self/exe").parent_path().parent_path();
  const fs::path script = demcal::testing::RepoRoot() / "bench/compare_export_heap.sh";
  const std::string command = "BUILD_DIR='" + build.string() +
                              "' REPS=8 ROLLING=none CHECK=1 bash '" + script.string() + "'";
  CHECK(std::system(command.c_str()) == 0);
}
