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
#include "core/walls/wall_test_support.h"

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
  enum Item { kTime, kSteps, kPosition, kRadius = kPosition + 5, kMass, kInvMass, kInvInertia,
              kSpecies, kMaterial, kBody, kId, kClumpPosition,
              kClumpInertia = kClumpPosition + 3, kClumpMass,
              kMemberSlot = kClumpPosition + 10, kRowStart = kClumpPosition + 12, kPartner,
              kReference, kPairHistory, kPairActive, kWallStart,
              kWallIndex, kWallHistory, kWallActive, kMeshSlots, kMeshHistory };

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
    for (int k = 0; k < 2; ++k) Vector(sizeof(uint32_t));  // rows, partners
    Vector(sizeof(Vec3));                                  // reference positions
    end_ += 8 + 8 + 4;                                     // half skin², builds, first fixed
    Vector(sizeof(ContactHistory)), Vector(1);             // pair histories, flags
    Vector(4), Vector(4);                                  // wall candidate rows, wall index
    Vector(sizeof(ContactHistory)), Vector(1), Vector(4);  // wall histories, flags, mesh slots
    Vector(kMeshHistoryBytes);                             // mesh histories
  }
  // WallContacts::MeshHistory: kMaxMeshContacts slots of (key, history), then count and padding.
  static constexpr size_t kMeshSlotBytes = 8 + sizeof(ContactHistory);
  static constexpr size_t kMeshHistoryBytes = WallContacts::kMaxMeshContacts * kMeshSlotBytes + 8;
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

template <class T>
T Read(const std::string& payload, size_t offset) {
  T value;
  std::memcpy(&value, payload.data() + offset, sizeof(T));
  return value;
}

// The checkpoint after `seconds` of `scene`.
std::string CheckpointOf(const Scene& scene, double seconds) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("demcal_integrity_physics_" + std::to_string(::getpid()) + ".bin"))
                               .string();
  std::string err;
  Simulation sim(scene, {.threads = 1});
  REQUIRE(sim.Initialize(&err));
  REQUIRE(sim.Run(seconds).ok());
  REQUIRE(sim.SaveCheckpoint(path, &err));
  std::ifstream in(path, std::ios::binary);
  std::string b((std::istreambuf_iterator<char>(in)), {});
  std::filesystem::remove(path);
  return b;
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
  // Format 7 (before the factories' carried clump draws): refused by its version, not misread.
  std::string seven = good;
  const uint32_t version7 = 7;
  std::memcpy(seven.data() + 8, &version7, 4);
  CHECK_THAT(Load(seven), Catch::Contains("format version 7; this build reads version 8 (written "
                                          "by another demcal build"));
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
  // mass, active time, full batches, region lift), its carried draws (none here: a count of 0),
  // then (no sinks here) the last sink pass step.
  REQUIRE(Read<uint64_t>(payload, payload.size() - 16) == 0);
  CHECK_THAT(Load(Edited(payload, payload.size() - 64 - 16, -1e300)),
             Catch::Contains("factories[0] 'feed': next batch time -1e+300 s outside"));
  // A NaN region lift gave the insertion grid NaN bounds (found by fuzz_checkpoint, UBSan); a lift
  // on a factory that does not follow the heap is not a state a run can reach.
  CHECK_THAT(Load(Edited(payload, payload.size() - 24, nan)), Catch::Contains("region lift nan m"));
  CHECK_THAT(Load(Edited(payload, payload.size() - 24, 0.5)),
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

TEST_CASE("edits that break the physics of the state are refused naming the check",
          "[unit][checkpoint]") {
  const std::string payload = Payload(Reference());
  const Layout at(payload);
  size_t free = 0;  // the first sphere that is not a clump member
  while (Read<int>(payload, at.At(Layout::kBody) + 4 * free) >= 0) ++free;
  REQUIRE(free < at.Count(Layout::kBody));
  const std::string sphere = "particles: slot " + std::to_string(free) + " (id ";
  const size_t mass = at.At(Layout::kMass) + 8 * free;
  // 1e-9 relative: far above round-off (1e-12), far below anything a run could tell apart.
  const std::string edited_mass = Edited(payload, mass, Read<double>(payload, mass) * (1 + 1e-9));
  CHECK_THAT(Load(edited_mass), Catch::Contains(sphere));
  CHECK_THAT(Load(edited_mass), Catch::Contains("mass or inertia edited without the radius?"));
  const size_t inertia = at.At(Layout::kInvInertia) + 8 * free;
  CHECK_THAT(Load(Edited(payload, inertia, Read<double>(payload, inertia) * 2)),
             Catch::Contains("is not that of a sphere of radius"));
  const size_t inv_mass = at.At(Layout::kInvMass) + 8 * free;
  CHECK_THAT(Load(Edited(payload, inv_mass, Read<double>(payload, inv_mass) * 0.5)),
             Catch::Contains("is not that of a sphere of radius"));
  // The first clump: its mass, its inertia, and its centre moved 0.1 mm from its spheres.
  REQUIRE(at.Count(Layout::kClumpMass) > 0);
  const size_t clump_mass = at.At(Layout::kClumpMass);
  CHECK_THAT(Load(Edited(payload, clump_mass, Read<double>(payload, clump_mass) * 1.01)),
             Catch::Contains("clumps: clump 0 (id "));
  const size_t clump_inertia = at.At(Layout::kClumpInertia) + 8;  // I2
  CHECK_THAT(Load(Edited(payload, clump_inertia, Read<double>(payload, clump_inertia) * 1.5)),
             Catch::Contains("or inertia is not that of its shape"));
  size_t member = 0;  // the first clump member sphere
  while (Read<int>(payload, at.At(Layout::kBody) + 4 * member) < 0) ++member;
  const size_t member_mass = at.At(Layout::kMass) + 8 * member;
  CHECK_THAT(Load(Edited(payload, member_mass, Read<double>(payload, member_mass) * 1.01)),
             Catch::Contains("a clump member whose mass is not its clump's"));
  const size_t centre = at.At(Layout::kClumpPosition);
  CHECK_THAT(Load(Edited(payload, centre, Read<double>(payload, centre) + 1e-4)),
             Catch::Contains("from where its shape puts it about the clump centre"));
  // An energy budget of 1e308 would switch the blow-up check off; so would a scale of 1e308.
  const size_t budget = at.At(Layout::kSteps) + 16, scale = budget + 8;
  CHECK_THAT(Load(Edited(payload, budget, 1e308)),
             Catch::Contains("checkpoint: energy budget 1e+308 J is"));
  CHECK_THAT(Load(Edited(payload, scale, 1e308)),
             Catch::Contains("checkpoint: energy scale 1e+308 J exceeds what the scene's"));
  // The factory's inserted bodies and mass (the 3rd and 4th of its 8 progress values, before
  // its empty carry and the last sink pass step): one body more than exist, or a mass its
  // bodies cannot have.
  REQUIRE(Read<uint64_t>(payload, payload.size() - 16) == 0);
  const size_t particles = payload.size() - 8 - 8 - 64 + 16;
  CHECK_THAT(Load(Edited(payload, particles, Read<int64_t>(payload, particles) + 1)),
             Catch::Contains("checkpoint: counters: "));
  CHECK_THAT(Load(Edited(payload, particles + 8, Read<double>(payload, particles + 8) * 3)),
             Catch::Contains("factories[0] 'feed': "));
}

TEST_CASE("absurd sink counters are refused", "[unit][checkpoint]") {
  Scene scene = PourScene();
  scene.sinks = {SinkSpec::Box("floor", {0, 0, -0.01}, {0.03, 0.03, 0.004})};
  const std::string payload = Payload(CheckpointOf(scene, 0.1));
  CHECK(Load(FrameCheckpoint(payload), scene).empty());
  // The reports of sink "floor" and of the domain (2 species each), then the last sink pass.
  const size_t report = 8 + 2 * 8 + 8 + 2 * 8 + 8;
  const size_t floor_count = payload.size() - 8 - 2 * report + 8;
  const int64_t removed = Read<int64_t>(payload, floor_count);
  REQUIRE(removed > 0);
  CHECK_THAT(Load(Edited(payload, floor_count, removed + 1), scene),
             Catch::Contains("checkpoint: counters: "));
  CHECK_THAT(Load(Edited(payload, floor_count, int64_t{1} << 40), scene),
             Catch::Contains("sink 'floor': 1099511627776 removed bodies of species 'balls'"));
}

TEST_CASE("a mesh history shared by two contacts or naming no feature is refused",
          "[unit][checkpoint]") {
  Scene scene = PourScene();
  scene.walls = {wall_test::MeshBox("box", {0, 0, 0}, {0.03, 0.03, 0.1}, /*open_top=*/true)};
  const std::string payload = Payload(CheckpointOf(scene, 0.1));
  CHECK(Load(FrameCheckpoint(payload), scene).empty());
  const Layout at(payload);
  const size_t histories = at.Count(Layout::kMeshHistory);
  size_t h = 0, base = 0;
  for (; h < histories; ++h) {
    base = at.At(Layout::kMeshHistory) + h * Layout::kMeshHistoryBytes;
    if (Read<uint32_t>(payload, base + Layout::kMeshHistoryBytes - 8) >= 1) break;
  }
  REQUIRE(h < histories);
  const uint64_t key = Read<uint64_t>(payload, base);
  // A second contact with the first one's key: two histories for one mesh feature.
  std::string shared = payload;
  std::memcpy(shared.data() + base + Layout::kMeshSlotBytes, &key, 8);
  const uint32_t two = 2;
  std::memcpy(shared.data() + base + Layout::kMeshHistoryBytes - 8, &two, 4);
  CHECK_THAT(Load(FrameCheckpoint(shared), scene),
             Catch::Contains("contacts 0 and 1 share the key " + std::to_string(key)));
  CHECK_THAT(Load(Edited(payload, base, uint64_t{999999}), scene),
             Catch::Contains("has the key 999999, which names no face, edge or vertex"));
}
