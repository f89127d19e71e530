// Repeatability of adhesive wall contacts: a run of a scene is a function of the scene and its
// seed alone, whatever the process did before. Every per-contact history starts value-
// initialised (contact_state.h); a JKR history that did not would start its Newton iteration
// from whatever the stack held (jkr.h, JkrNormal::Compute), so the same adhesive scene would end
// differently from run to run. Spheres with JKR adhesion (Γ > 0) fall on a plane floor and on a
// small triangle-mesh plate that is removed halfway, so new adhesive contacts form with both
// kinds of wall and with each other; the scene is run several times in one process, after the
// stack has been filled with different plausible contact radii, and every run's digest
// (particle state, contact count, wall loads and the checkpoint bytes, which hold every contact
// history) must be identical bit for bit. That catches state taken from reused heap memory; a
// value read from an uninitialised local is often the same stack bytes in every run (an
// uninitialised √a read 0 or −1.4e−182 here, run after run), so tests/CMakeLists.txt also runs
// this test under valgrind (memcheck.adhesive_wall_determinism), which reports any such read.
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/math/fnv1a.h"
#include "core/math/random.h"
#include "tests/core/walls/wall_test_support.h"
#include "core/io/scratch_dir.h"

namespace demcal::core {
namespace {

constexpr double kDiameter_m = 0.004;

// Plate of half-width 8 mm at z = 10 mm over a plane floor at z = 0; 4 × 4 × 3 spheres of 4 mm
// above them with small random velocities and spins, Γ = 0.05 J/m² for every pair (pull-off
// force 3πΓR* ≈ 1 mN against a weight of 0.8 mN: the spheres stick where they land).
Scene AdhesiveSpheresOnWalls() {
  Scene s = wall_test::OneMaterialScene(kDiameter_m);
  s.pair_parameters[0].interfacial_energy_J_m2 = 0.05;
  s.pair_parameters[0].rolling_friction = 0.1;
  s.rolling.name = "epsd2";
  s.walls.push_back(PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}});
  Wall plate = wall_test::MeshPlate("plate", 0.008, 0.01);
  plate.remove_at_s = 0.08;
  s.walls.push_back(plate);
  s.domain_min_m = {-0.03, -0.03, -0.005};
  s.domain_max_m = {0.03, 0.03, 0.05};
  Rng rng(5);
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) {
        const Vec3 at{-0.015 + 0.01 * x, -0.015 + 0.01 * y, 0.016 + 0.005 * z};
        const Vec3 jitter{rng.Uniform() - 0.5, rng.Uniform() - 0.5, rng.Uniform() - 0.5};
        s.particles.push_back({0, at, 0.05 * jitter, 20.0 * jitter, kDiameter_m, {}});
      }
  return s;
}

// Fills 256 KiB of the stack below the caller with `value` (a plausible square root of a contact
// radius, m^½), so that a run does not start on the stack the previous one left.
[[gnu::noinline]] void DirtyStack(double value) {
  volatile double junk[32768];
  for (volatile double& x : junk) x = value;
}

std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

uint64_t RunDigest(const Scene& scene, const std::string& checkpoint_path) {
  Simulation sim(scene, {.threads = 1});
  wall_test::InitializeOrFail(sim);
  const RunSummary run = sim.Run(0.12);
  INFO(run.BriefReport());
  REQUIRE(run.ok());
  const Particles& p = sim.particles();
  Fnv1a64 h;
  for (size_t i = 0; i < p.Size(); ++i) {
    h.Field(p.id[i]);
    h.Field(p.position_m[i]), h.Field(p.velocity_m_s[i]), h.Field(p.angular_velocity_rad_s[i]);
  }
  h.Field(static_cast<uint64_t>(sim.ActiveContacts()));
  for (const WallLoad& load : sim.WallLoads()) h.Field(load.force_N), h.Field(load.torque_N_m);
  std::string error;
  const bool saved = sim.SaveCheckpoint(checkpoint_path, &error);
  INFO(error);
  REQUIRE(saved);
  h.Text(FileBytes(checkpoint_path));
  return h.digest();
}

}  // namespace

TEST_CASE("an adhesive scene on a plane and a mesh wall repeats bit for bit in one process",
          "[unit][physics][determinism]") {
  const Scene scene = AdhesiveSpheresOnWalls();
  // One folder per process: the memcheck run of this case (tests/CMakeLists.txt) runs beside it.
  const demcal::testing::ScratchDir dir("adhesive_wall_determinism");
  const std::string checkpoint = dir.str("state.ckpt");

  // The scene does what the test relies on: spheres rest on the floor and the plate, held by
  // adhesion, and some of them fell from the plate to the floor after it was removed.
  {
    Simulation sim(scene, {.threads = 1});
    wall_test::InitializeOrFail(sim);
    REQUIRE(sim.Run(0.07).ok());
    const std::vector<WallLoad> on_plate = sim.WallLoads();
    CHECK(on_plate[0].force_N.z < 0);  // both walls carry spheres
    CHECK(on_plate[1].force_N.z < 0);
    REQUIRE(sim.Run(0.05).ok());
    CHECK(sim.WallLoads()[1].force_N.z == 0);  // the plate is gone
    size_t on_floor = 0;
    for (const Vec3& x : sim.particles().position_m) on_floor += x.z < kDiameter_m;
    CHECK(on_floor > 16);  // more than the outer columns' bottom layer
  }

  const uint64_t reference = RunDigest(scene, checkpoint);
  // √a of a JKR contact here is about 0.005–0.01 m^½; 1 is far off the branch.
  for (const double stack_value : {0.007, 0.004, 1.0, 0.0}) {
    DirtyStack(stack_value);
    INFO("stack filled with " << stack_value);
    CHECK(RunDigest(scene, checkpoint) == reference);
  }
}

}  // namespace demcal::core
