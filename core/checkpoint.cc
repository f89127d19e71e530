// Simulation checkpoints: one binary file, "demcal-checkpoint/N", holding the whole dynamic
// state in the order SerializeState lists it, behind a header that identifies the scene.
#include <fstream>
#include <sstream>

#include "core/archive.h"
#include "core/simulation.h"

namespace demcal::core {
namespace {
// 2: mesh wall histories, wall loads; 3: JKR radius; 4: fixed spheres last, out of the list;
// 5: sink tallies, factory region lift
constexpr char kMagic[] = "demcal-checkpoint/5";
}  // namespace

template <class A>
void Simulation::SerializeState(A& a) {
  std::string magic = kMagic;
  a.String(magic);
  uint64_t seed = scene_.seed, species = scene_.species.size(), walls = scene_.walls.size(),
           factories = factories_.size();
  a.Value(seed), a.Value(species), a.Value(walls), a.Value(factories), a.Value(dt_);
  if (!a.writing() && (magic != kMagic || seed != scene_.seed || species != scene_.species.size() ||
                       walls != scene_.walls.size() || factories != factories_.size())) {
    throw std::runtime_error("the checkpoint was written for a different scene (seed, species, "
                             "walls, factories or time step differ) or is not a demcal checkpoint");
  }
  a.Value(time_s_), a.Value(steps_), a.Value(rebuilds_since_reorder_);
  a.Value(energy_budget_J_), a.Value(energy_scale_J_);
  system_.Serialize(a);
  list_.Serialize(a);
  forces_.Serialize(a);
  for (ParticleFactory& f : factories_) f.Serialize(a);
  for (SinkReport& r : sink_reports_) r.Serialize(a);
  a.Value(last_sink_pass_step_);
}

bool Simulation::SaveCheckpoint(const std::string& path, std::string* error) const {
  Archive a = Archive::ForWriting();
  const_cast<Simulation*>(this)->SerializeState(a);  // writing leaves the state unchanged
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(a.bytes().data(), static_cast<std::streamsize>(a.bytes().size()));
  if (!out) {
    if (error) *error = "cannot write checkpoint file '" + path + "'";
    return false;
  }
  return true;
}

bool Simulation::LoadCheckpoint(const std::string& path, std::string* error) {
  if (!initialized_) {
    if (error) *error = "Initialize() the simulation from its scene before loading a checkpoint";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) {
    if (error) *error = "cannot read checkpoint file '" + path + "'";
    return false;
  }
  Archive a = Archive::ForReading(bytes.str());
  try {
    SerializeState(a);
  } catch (const std::exception& e) {
    if (error) *error = "checkpoint '" + path + "': " + e.what();
    return false;
  }
  if (!a.ok()) {
    if (error) *error = "checkpoint '" + path + "' is truncated or corrupt";
    return false;
  }
  PlaceWalls(time_s_);
  WallRemovedDuringStep(time_s_);
  return true;
}

}  // namespace demcal::core
