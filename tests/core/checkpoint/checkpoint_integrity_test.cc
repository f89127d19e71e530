// Checkpoints verified on load: another scene or time step, appended junk, truncation,
// byte flips and hand edits are each refused with the check that failed, never a crash, a hang
// or a run on NaN. "Reframed" edits recompute the checksum, so they reach the state checks
// behind it (a deliberate edit, or damage the checksum would miss).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include <unistd.h>

#include "core/checkpoint/checkpoint_file.h"
#include "core/checkpoint/checkpoint_scene.h"
#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

// Poured spheres and 2-sphere clumps in a 30 × 30 × 100 mm box, fed from 20–50 mm up.
Scene PourScene() {
  return checkpoint_test::PourScene({.box_max_m = {0.03, 0.03, 0.1},
                                     .interfacial_energy_J_m2 = 0.02,
                                     .feed_radius_m = 0.012,
                                     .feed_z_lo_m = 0.02,
                                     .feed_z_hi_m = 0.05,
                                     .feed_rate_kg_s = 0.01,
                                     .seed = 11});
}

// The checkpoint of PourScene after 0.1 s (particles on the floor, clumps, wall contacts).
const std::string& Reference() {
  static const std::string bytes = [] {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("demcal_integrity_" + std::to_string(::getpid()) + ".bin"))
                                 .string();
    std::string err;
    Simulation sim(PourScene(), {.threads = 1});
    REQUIRE(sim.Initialize(&err));
    REQUIRE(sim.Run(0.1).ok());
    REQUIRE(sim.system().clumps.Size() > 0);
    REQUIRE(sim.ActiveContacts() > 0);
    REQUIRE(sim.SaveCheckpoint(path, &err));
    std::ifstream in(path, std::ios::binary);
    std::string b((std::istreambuf_iterator<char>(in)), {});
    std::filesystem::remove(path);
    return b;
  }();
  return bytes;
}

// Loads `bytes` into a fresh simulation of `scene`; the refusal message, or "" if accepted (then
// a short run must end in a defined termination, never a crash).
std::string Load(const std::string& bytes, const Scene& scene = PourScene()) {
  Simulation sim(scene, {.threads = 1});
  std::string err;
  REQUIRE(sim.Initialize(&err));
  if (!sim.LoadCheckpointBytes(bytes, "cp.bin", &err)) return err;
  const RunSummary run = sim.Run(0.002);
  CHECK((run.ok() || !run.message.empty()));
  return "";
}

std::string Payload(const std::string& file) { return file.substr(kCheckpointHeaderBytes); }

// Offsets of the payload's items, walked in SerializeState's order (At(k): where item k's data
// starts, after the length of a vector).
class Layout {
 public:
  enum Item { kTime, kSteps, kPosition, kRadius = kPosition + 5, kSpecies = kRadius + 4,
              kMaterial, kBody, kId, kClumpPosition, kMemberSlot = kClumpPosition + 10,
              kRowStart = kClumpPosition + 12, kPartner, kReverseStart, kReverseEntry,
              kReference, kPairHistory, kPairActive, kWallStart, kWallIndex };

  explicit Layout(const std::string& payload) : p_(payload) {
    const uint64_t parts = U64(0);
    end_ = 8;
    for (uint64_t k = 0; k < parts; ++k) end_ += 8 + U64(end_) + 8;  // name, digest
    end_ += 8;  // Δt
    Value(8), Value(8);  // time, steps
    end_ += 3 * 8;       // rebuilds, energy budget and scale
    for (int k = 0; k < 5; ++k) Vector(sizeof(Vec3));    // x, v, ω, F, T
    for (int k = 0; k < 4; ++k) Vector(sizeof(double));  // radius, mass, 1/m, 1/I
    for (int k = 0; k < 3; ++k) Vector(sizeof(int));     // species, material, body
    Vector(sizeof(int64_t));                             // id
    for (size_t e : {sizeof(Vec3), sizeof(Vec3), sizeof(RigidState), sizeof(Vec3), sizeof(double),
                     sizeof(Vec3), sizeof(Vec3), sizeof(int), sizeof(int64_t), sizeof(uint32_t),
                     sizeof(uint32_t), sizeof(Vec3)})
      Vector(e);  // clumps
    end_ += 8;    // next id
    for (int k = 0; k < 4; ++k) Vector(sizeof(uint32_t));  // rows, partners, reverse index
    Vector(sizeof(Vec3));                                  // reference positions
    end_ += 8 + 8 + 4;                                     // half skin², builds, first fixed
    Vector(sizeof(ContactHistory)), Vector(1);             // pair histories, flags
    Vector(4), Vector(4);                                  // wall candidate rows, wall index
  }
  size_t At(Item k) const { return start_.at(k); }
  uint64_t Count(Item k) const { return U64(start_.at(k) - 8); }

 private:
  uint64_t U64(size_t o) const {
    uint64_t v;
    std::memcpy(&v, p_.data() + o, 8);
    return v;
  }
  void Value(size_t bytes) {
    start_.push_back(end_);
    end_ += bytes;
  }
  void Vector(size_t element) {
    start_.push_back(end_ + 8);
    end_ += 8 + U64(end_) * element;
  }
  const std::string& p_;
  std::vector<size_t> start_;
  size_t end_ = 0;
};

template <class T>
std::string Edited(std::string payload, size_t offset, T value) {
  std::memcpy(payload.data() + offset, &value, sizeof(T));
  return FrameCheckpoint(payload);
}

}  // namespace

TEST_CASE("a valid checkpoint is accepted", "[unit][checkpoint]") {
  CHECK(Load(Reference()).empty());
}

TEST_CASE("a checkpoint of another scene or time step is refused, naming what differs",
          "[unit][checkpoint]") {
  Scene more = PourScene();
  more.fills = {{0, {0.002, 0.002, 0.06}, {0.028, 0.028, 0.09}, 100, {}}};
  CHECK_THAT(Load(Reference(), more), Catch::Contains("cp.bin: checkpoint: written for another "
                                                      "scene: initial particles differs"));
  Scene other_dt = PourScene();
  other_dt.time.rayleigh_fraction = 0.1;
  CHECK_THAT(Load(Reference(), other_dt),
             Catch::Contains("cp.bin: checkpoint: written for another time step"));
  Scene walls = PourScene();
  walls.walls.pop_back();
  CHECK_THAT(Load(Reference(), walls), Catch::Contains("walls, wall motion differ"));
  Scene friction = PourScene();
  friction.pair_parameters[0].sliding_friction = 0.3;
  CHECK_THAT(Load(Reference(), friction), Catch::Contains("contact parameters differs"));
}

TEST_CASE("appended, truncated and flipped checkpoints are refused by the envelope",
          "[unit][checkpoint]") {
  const std::string& good = Reference();
  CHECK_THAT(Load(good + std::string(1000, 'x')),
             Catch::Contains("checkpoint: 1000 unexpected bytes after the end"));
  std::vector<size_t> cuts;  // every length up to a header and a bit, then 60 spread over the file
  for (size_t cut = 0; cut <= 40; ++cut) cuts.push_back(cut);
  for (size_t k = 1; k <= 60; ++k) cuts.push_back(k * (good.size() - 1) / 60);
  for (size_t cut : cuts)
    CHECK_THAT(Load(good.substr(0, cut)), Catch::Contains("checkpoint: truncated"));
  for (uint32_t seed = 1; seed <= 200; ++seed) {
    std::mt19937 rng(seed);
    std::string bad = good;
    for (int k = 0; k < 20; ++k)
      bad[std::uniform_int_distribution<size_t>(0, bad.size() - 1)(rng)] ^=
          static_cast<char>(1 + rng() % 255);
    const std::string why = Load(bad);
    CHECK_FALSE(why.empty());
    CHECK_THAT(why, Catch::StartsWith("cp.bin: checkpoint: "));
  }
  std::string one = good;
  one[one.size() / 2] ^= 1;
  CHECK_THAT(Load(one), Catch::Contains("checksum mismatch"));
  std::string old = good;
  const uint64_t length = 19;
  std::memcpy(old.data(), &length, 8);
  std::memcpy(old.data() + 8, "demcal-checkpoint/4", 19);
  CHECK_THAT(Load(old), Catch::Contains("format 'demcal-checkpoint/4' of an older demcal"));
}

TEST_CASE("hand-edited checkpoints with a valid checksum are refused by the state checks",
          "[unit][checkpoint]") {
  const std::string payload = Payload(Reference());
  const Layout at(payload);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kTime), nan)), Catch::Contains("time nan s"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kSteps), std::numeric_limits<int64_t>::max())),
             Catch::Contains("step count 9223372036854775807 does not match the time"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kSpecies), 99)),
             Catch::Contains("particles: slot 0 (id"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kBody), 100000)),
             Catch::Contains("clump index 100000"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kRadius), 1.0)),
             Catch::Contains("radius 1 m outside"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kRadius), nan)), Catch::Contains("radius nan m"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kMaterial), 3)),
             Catch::Contains("material index 3 is not its species' material"));
  int64_t first_id;
  std::memcpy(&first_id, payload.data() + at.At(Layout::kId), 8);
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kId) + 8, first_id)),
             Catch::Contains("particles: id " + std::to_string(first_id) + " appears twice"));
  REQUIRE(at.Count(Layout::kMemberSlot) > 0);
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kMemberSlot), uint32_t{4000000000u})),
             Catch::Contains("member slot 4000000000 is not a sphere of this clump"));
  REQUIRE(at.Count(Layout::kPartner) > 0);
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kPartner), uint32_t{4000000000u})),
             Catch::Contains("lists partner 4000000000"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kReverseEntry), uint32_t{4000000000u})),
             Catch::Contains("neighbour list: the reverse index does not match the rows"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kRowStart) + 4, uint32_t{4000000000u})),
             Catch::Contains("neighbour list: rows do not match"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kReference), 0.5)),
             Catch::Contains("more than half the skin"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kPairHistory), nan)),
             Catch::Contains("contact histories: entry 0 has a non-finite history"));
  REQUIRE(at.Count(Layout::kWallIndex) > 0);
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kWallIndex), uint32_t{77})),
             Catch::Contains("wall index 77 (the scene has 5 walls)"));
  CHECK_THAT(Load(Edited(payload, at.At(Layout::kPosition) + 8, nan)),
             Catch::Contains("non-finite position"));
  // The payload cut short or lengthened, then reframed.
  CHECK_THAT(Load(FrameCheckpoint(payload.substr(0, payload.size() - 9))),
             Catch::Contains("the payload ends before the state is complete"));
  CHECK_THAT(Load(FrameCheckpoint(payload + "junk")), Catch::Contains("4 bytes left over"));
  // The factory's next batch far in the past would loop over batches for ever.
  // The factory's 8 progress values (next batch, owed mass, particles, inserted and requested
  // mass, active time, full batches, region lift), then (no sinks here) the last sink pass step.
  CHECK_THAT(Load(Edited(payload, payload.size() - 64 - 8, -1e300)),
             Catch::Contains("factories[0] 'feed': next batch time -1e+300 s outside"));
  // A NaN region lift gave the insertion grid NaN bounds (found by fuzz_checkpoint, UBSan); a lift
  // on a factory that does not follow the heap is not a state a run can reach.
  CHECK_THAT(Load(Edited(payload, payload.size() - 16, nan)), Catch::Contains("region lift nan m"));
  CHECK_THAT(Load(Edited(payload, payload.size() - 16, 0.5)),
             Catch::Contains("set on a factory that does not follow the heap"));
  // A last sink pass ahead of the step counter would postpone every later pass.
  CHECK_THAT(Load(Edited(payload, payload.size() - 8, int64_t{1} << 50)),
             Catch::Contains("last sink pass at step 1125899906842624, outside [0, "));
  CHECK_THAT(Load(Edited(payload, payload.size() - 8, int64_t{-3})),
             Catch::Contains("last sink pass at step -3"));
  CHECK_THAT(Load(Edited(payload, 0, uint64_t{1} << 40)),
             Catch::Contains("the scene fingerprint claims 1099511627776 parts"));
}

TEST_CASE("random edits behind a valid checksum never crash the loader or the run",
          "[unit][checkpoint]") {
  const std::string payload = Payload(Reference());
  int refused = 0;
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    std::mt19937 rng(seed);
    std::string bad = payload;
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < flips; ++k)
      bad[std::uniform_int_distribution<size_t>(0, bad.size() - 1)(rng)] ^=
          static_cast<char>(1u << (rng() % 8));
    refused += !Load(FrameCheckpoint(bad)).empty();
  }
  // Most flips land in histories and positions whose damage is only caught when not finite or
  // out of range; what matters is that none crashed. Some must have been refused.
  CHECK(refused > 10);
}
