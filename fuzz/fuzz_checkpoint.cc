// libFuzzer harness: the checkpoint reader (Simulation::LoadCheckpointBytes) and, for every
// checkpoint it accepts, a few steps of the restored run. Never crashes, hangs or leaks; a
// refusal names the file and the failed check ("cp.bin: checkpoint: ...").
//
// Input: one mode byte, then the file. Mode bit 0 set: the envelope is repaired (payload length
// and checksum recomputed, the FrameCheckpoint of the rest after the 32-byte header), so the
// mutations reach the fingerprint and state checks behind the checksum; clear: the bytes as
// they are (the envelope checks). Seed: `DEMCAL_FUZZ_WRITE_SEED=DIR ./fuzz_checkpoint` writes a
// valid checkpoint of the scene below, in both modes, into DIR and exits.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>

#include "core/checkpoint/checkpoint_file.h"
#include "core/simulation/simulation.h"
#include "core/walls/triangle_mesh.h"
#include "tests/core/checkpoint/checkpoint_scene.h"

using namespace demcal::core;

namespace {

// Spheres and 2-sphere clumps poured into a box of planes, onto a mesh plate, beside a rising
// post (cylinder) and under a funnel (cone): every kind of state a checkpoint holds.
Scene FuzzScene() {
  Scene s = checkpoint_test::PourScene({.box_max_m = {0.02, 0.02, 0.05},
                                        .interfacial_energy_J_m2 = 0.01,
                                        .feed_radius_m = 0.007,
                                        .feed_z_lo_m = 0.006,
                                        .feed_z_hi_m = 0.02,
                                        .feed_rate_kg_s = 0.002,
                                        .seed = 3});
  std::string error;
  const std::array<int32_t, 3> triangles[] = {{0, 1, 2}, {0, 2, 3}};
  auto plate = TriangleMesh::FromIndexed(
      {{0.002, 0.002, 0.002}, {0.018, 0.002, 0.002}, {0.018, 0.018, 0.002}, {0.002, 0.018, 0.002}},
      triangles, {}, &error);
  if (!plate) std::abort();
  s.walls.push_back(Wall("plate", 0, MeshRef{std::make_shared<const TriangleMesh>(*plate), {}, "plate"}));
  Wall post("post", 0, CylinderSurface{.axis_point_m = {0.004, 0.004, 0}, .radius_m = 0.0015,
                                       .inside = false});
  post.velocity_m_s = {0, 0, 0.05};
  s.walls.push_back(post);
  s.walls.push_back(Wall("funnel", 0, ConeFrustumSurface{.axis_point_m = {0.01, 0.01, 0},
                                                         .height0_m = 0.03, .radius0_m = 0.004,
                                                         .height1_m = 0.045, .radius1_m = 0.009}));
  return s;
}

const Scene& TheScene() {
  static const Scene scene = FuzzScene();
  return scene;
}

void WriteSeeds(const std::string& dir) {
  Simulation sim(TheScene(), {.threads = 1});
  std::string error;
  const std::string path = dir + "/valid.ckpt";
  if (!sim.Initialize(&error) || !sim.Run(0.05).ok() || !sim.SaveCheckpoint(path, &error)) {
    std::fprintf(stderr, "fuzz_checkpoint: cannot write the seed: %s\n", error.c_str());
    std::exit(1);
  }
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  for (char mode : {'\0', '\1'})
    std::ofstream(dir + "/seed_mode" + std::to_string(int(mode)), std::ios::binary) << mode << bytes;
  std::remove(path.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("DEMCAL_FUZZ_WRITE_SEED")) {
    WriteSeeds(dir);
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  std::string file(reinterpret_cast<const char*>(data + 1), size - 1);
  if ((data[0] & 1) && file.size() >= kCheckpointHeaderBytes)
    file = FrameCheckpoint(file.substr(kCheckpointHeaderBytes));
  Simulation sim(TheScene(), {.threads = 1});
  std::string error;
  if (!sim.Initialize(&error)) std::abort();
  if (!sim.LoadCheckpointBytes(file, "cp.bin", &error)) {
    if (error.rfind("cp.bin: checkpoint: ", 0) != 0) std::abort();
    return 0;
  }
  sim.Run(20 * sim.timestep_s());  // an accepted state must run (or fail cleanly), never crash
  return 0;
}
