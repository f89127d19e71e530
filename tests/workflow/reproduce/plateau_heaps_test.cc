// The clumps workflow calibrates each species' shape on a repose heap past the clumps' size
// plateau (docs/experiments/segregation_angle.md: at size x5 a clump heap's angle rises with the
// heap's size up to about 8 grain lengths). The plateau was measured on BP's heap
// (bench/clump_heap_size.py, arm M); TAED's and EP's heaps rely on being the same heap in their
// own grain diameters: lengths x r, mass x (rho / rho_BP) r^2, r = d / d_BP
// (bench/clump_plateau_calibration.py). A file edited without its rule would calibrate a species
// on a heap that may stand below the plateau again.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "workflow/test_paths.h"

namespace demcal::workflow {
namespace {

nlohmann::json Read(const std::string& relative) {
  std::ifstream in(testing::RepoRoot() / relative);
  REQUIRE(in);
  return nlohmann::json::parse(in);
}

struct Heap {
  double d = 0, rho = 0, mass = 0, width = 0, height = 0, feed = 0, depth = 0;
};

Heap HeapOf(const std::string& file) {
  const nlohmann::json e = Read(file);
  const nlohmann::json& species = e.at("species").at(0);
  Heap h;
  h.d = (species.at("diameter_range_m").at(0).get<double>() +
         species.at("diameter_range_m").at(1).get<double>()) / 2;
  for (const auto& m : e.at("materials"))
    if (m.at("name") == species.at("material")) h.rho = m.at("density_kg_m3").get<double>();
  const nlohmann::json& aor = e.at("aor");
  h.mass = aor.at("feed").at("mass_kg").get<double>();
  h.width = aor.at("width_m").get<double>();
  h.height = aor.at("pour_height_m").get<double>();
  h.feed = aor.at("feed_width_m").get<double>();
  h.depth = aor.at("depth_m").get<double>();
  return h;
}

TEST_CASE("the clumps workflow's repose heaps are BP's plateau heap scaled to each grain",
          "[unit]") {
  const Heap bp = HeapOf("examples/aor_bp_plateau.json");
  for (const std::string name : {"taed", "ep"}) {
    INFO(name);
    const Heap h = HeapOf("examples/aor_" + name + "_plateau.json");
    const double r = h.d / bp.d;
    // 2 %: the files round their lengths and masses to 2-3 digits.
    CHECK(h.width / r == Approx(bp.width).epsilon(0.02));
    CHECK(h.height / r == Approx(bp.height).epsilon(0.02));
    CHECK(h.feed / r == Approx(bp.feed).epsilon(0.02));
    CHECK(h.mass / (h.rho * r * r) == Approx(bp.mass / bp.rho).epsilon(0.02));
    CHECK(h.depth == bp.depth);  // the paper's slab, the same for every heap
  }
  // BP's heap is arm M of bench/clump_heap_size.py, the smallest heap measured on the plateau.
  CHECK(bp.mass == Approx(0.010));
  CHECK(bp.width == Approx(0.12));
  CHECK(bp.height == Approx(0.09));
}

TEST_CASE("the clumps workflow calibrates every species and the coating on plateau heaps",
          "[unit]") {
  const nlohmann::json w = Read("datasets/alizadeh2018/workflow_clumps.json");
  for (const auto& species : w.at("species")) {
    INFO(species.at("name"));
    CHECK(species.at("experiment_file").get<std::string>().find("_plateau.json") !=
          std::string::npos);
  }
  CHECK(w.at("coating").at("experiment_file").get<std::string>().find("_plateau.json") !=
        std::string::npos);
}

}  // namespace
}  // namespace demcal::workflow
