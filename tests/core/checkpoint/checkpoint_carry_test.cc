// A clump factory's carried draws (core/insertion/factory.h) are factory state: a checkpoint
// holds them, a restart with draws pending continues bit-identically on another thread count,
// and damaged ones are refused naming the check.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/checkpoint/checkpoint_file.h"
#include "core/insertion/clump_pour_scene.h"
#include "core/math/fnv1a.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

std::string TempPath(const std::string& tag) {
  return (std::filesystem::temp_directory_path() /
          ("demcal_checkpoint_carry_" + tag + "_" + std::to_string(::getpid()) + ".bin"))
      .string();
}

// A 12 mm region asked for more than it holds (clump_carry_test.cc): after its first batch,
// draws wait in the carry.
Scene OverfedSlot() {
  return clump_pour::ClumpPour(InsertionRegion::Box({0, 0, 0}, {0.012, 0.016, 0.03}), 0.017,
                               0.0025);
}

// Starts `sim` and runs it half a batch past its first: the carry holds draws.
void RunPastFirstBatch(Simulation& sim) {
  std::string err;
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(1.5 * sim.factories()[0].batch_interval_s()).ok());
  REQUIRE_FALSE(sim.factories()[0].carried().empty());
}

std::string FileOf(const Simulation& sim, const std::string& path) {
  std::string err;
  REQUIRE(sim.SaveCheckpoint(path, &err));
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::remove(path.c_str());
  return bytes;
}

// The refusal of `payload` (reframed) by a fresh simulation of `scene`; empty if accepted.
std::string Load(const Scene& scene, const std::string& payload) {
  Simulation sim(scene, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  return sim.LoadCheckpointBytes(FrameCheckpoint(payload), "cp.bin", &err) ? "" : err;
}

}  // namespace

TEST_CASE("a restart with a clump factory's carried draws pending continues bit-identically",
          "[unit][checkpoint]") {
  const std::string path = TempPath("restart");
  const Scene s = OverfedSlot();
  REQUIRE(!s.species.empty());
  Simulation reference(s, {.threads = 2});
  RunPastFirstBatch(reference);
  const std::vector<CarriedDraw> pending = reference.factories()[0].carried();
  std::string err;
  REQUIRE(reference.SaveCheckpoint(path, &err));
  REQUIRE(reference.Run(0.15).ok());

  Simulation restarted(s, {.threads = 1});
  REQUIRE(restarted.Initialize(&err));
  REQUIRE(restarted.LoadCheckpoint(path, &err));
  std::remove(path.c_str());
  CHECK(restarted.factories()[0].carried() == pending);
  REQUIRE(restarted.Run(0.15).ok());
  CHECK(restarted.system().clumps.Size() == reference.system().clumps.Size());
  // The whole state, carry included: the digests of the checkpoints both write now.
  CHECK(Fnv1a64Of(FileOf(restarted, path)) == Fnv1a64Of(FileOf(reference, path)));
}

TEST_CASE("damaged carried draws in a checkpoint are refused", "[unit][checkpoint]") {
  const Scene s = OverfedSlot();
  REQUIRE(!s.species.empty());
  Simulation sim(s, {.threads = 1});
  RunPastFirstBatch(sim);
  const size_t n = sim.factories()[0].carried().size();
  const std::string payload = FileOf(sim, TempPath("damaged")).substr(kCheckpointHeaderBytes);
  CHECK(Load(s, payload).empty());
  // The payload ends with the carry (count, then 16 bytes per draw: mixture index, diameter)
  // and, no sinks here, the last sink pass step.
  const size_t count_at = payload.size() - 8 - 16 * n - 8;
  uint64_t count = 0;
  std::memcpy(&count, payload.data() + count_at, 8);
  REQUIRE(count == n);
  auto edited = [&](size_t offset, auto value) {
    std::string p = payload;
    std::memcpy(p.data() + offset, &value, sizeof(value));
    return p;
  };
  const size_t first = count_at + 8;
  CHECK_THAT(Load(s, edited(first, int64_t{5})),
             Catch::Contains("factories[0] 'feed': carried draw 0: mixture index 5 (of 1)"));
  CHECK_THAT(Load(s, edited(first + 8, 0.003)),
             Catch::Contains("diameter 0.003 m not of its species"));
  // More draws than were ever asked for: 10,000 of the largest.
  std::string many = payload.substr(0, count_at);
  const uint64_t extra = 10000;
  many.append(reinterpret_cast<const char*>(&extra), 8);
  for (uint64_t k = 0; k < extra; ++k) {
    const int64_t index = 0;
    const double d = clump_pour::kDMax;
    many.append(reinterpret_cast<const char*>(&index), 8);
    many.append(reinterpret_cast<const char*>(&d), 8);
  }
  many.append(payload.substr(payload.size() - 8));
  CHECK_THAT(Load(s, many), Catch::Contains("10000 carried draws weigh"));
}
