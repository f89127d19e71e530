// Simulation checkpoints: the whole dynamic state in the order SerializeState lists it, behind
// the scene's fingerprint, inside the verified envelope of core/checkpoint/checkpoint_file.h. Loading
// believes nothing before it is checked: envelope (length, checksum), fingerprint (the scene and
// time step it was written for), then every count and index of the restored state
// (CheckRestoredState, core/checkpoint_checks_*.cc). A refusal names the failed check.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/checkpoint/archive.h"
#include "core/checkpoint/checkpoint_file.h"
#include "core/scene/scene_fingerprint.h"
#include "core/simulation/simulation.h"

namespace demcal::core {
namespace {
// More parts than any build writes: a damaged count is refused before the loop.
constexpr uint64_t kMaxFingerprintParts = 64;

struct CheckpointRefusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string Number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}
}  // namespace

std::vector<FingerprintPart> Simulation::Fingerprint() const {
  return SceneFingerprint(scene_, dt_, list_settings_.skin_m);
}

template <class A>
void Simulation::SerializeState(A& a, const std::vector<std::string>& may_differ) {
  std::vector<FingerprintPart> parts;
  if (a.writing()) parts = Fingerprint();
  uint64_t count = parts.size();
  a.Value(count);
  if (!a.writing() && a.ok()) {
    if (count > kMaxFingerprintParts)
      throw CheckpointRefusal("the scene fingerprint claims " + std::to_string(count) + " parts");
    parts.resize(count);
  }
  for (FingerprintPart& p : parts) a.String(p.name), a.Value(p.digest);
  double dt = dt_;
  a.Value(dt);
  if (!a.writing() && a.ok()) {
    if (dt != dt_)
      throw CheckpointRefusal("written for another time step: " + Number(dt) +
                              " s in the checkpoint, " + Number(dt_) + " s in this scene");
    const std::string differ = DifferingParts(parts, Fingerprint(), may_differ);
    if (!differ.empty())
      throw CheckpointRefusal("written for another scene: " + differ +
                              (differ.find(',') == std::string::npos ? " differs" : " differ"));
  }
  a.Value(time_s_), a.Value(steps_), a.Value(rebuilds_since_reorder_);
  a.Value(energy_budget_J_), a.Value(energy_scale_J_);
  system_.Serialize(a);
  list_.Serialize(a);
  forces_.Serialize(a);
  uint64_t factories = factories_.size();
  a.Value(factories);
  if (!a.writing() && a.ok() && factories != factories_.size())
    throw CheckpointRefusal("holds " + std::to_string(factories) + " factories, the scene " +
                            std::to_string(factories_.size()));
  for (ParticleFactory& f : factories_) f.Serialize(a);
  for (SinkReport& r : sink_reports_) r.Serialize(a);
  a.Value(last_sink_pass_step_);
}

bool Simulation::SaveCheckpoint(const std::string& path, std::string* error) const {
  Archive a = Archive::ForWriting();
  const_cast<Simulation*>(this)->SerializeState(a, {});  // writing leaves the state unchanged
  return WriteCheckpointFile(path, a.bytes(), error);
}

bool Simulation::LoadCheckpoint(const std::string& path, std::string* error,
                                const std::vector<std::string>& may_differ) {
  std::string payload, why;
  if (!ReadCheckpointFile(path, &payload, &why)) {
    if (error) *error = path + ": checkpoint: " + why;
    return false;  // the state is untouched
  }
  return LoadCheckpointPayload(payload, path, error, may_differ);
}

bool Simulation::LoadCheckpointBytes(const std::string& file_bytes, const std::string& name,
                                     std::string* error, const std::vector<std::string>& may_differ) {
  std::string payload, why;
  if (!UnframeCheckpoint(file_bytes, &payload, &why)) {
    if (error) *error = name + ": checkpoint: " + why;
    return false;
  }
  return LoadCheckpointPayload(payload, name, error, may_differ);
}

bool Simulation::LoadCheckpointPayload(const std::string& payload, const std::string& name,
                                       std::string* error,
                                       const std::vector<std::string>& may_differ) {
  auto refuse = [&](const std::string& why) {
    if (error) *error = name + ": checkpoint: " + why;
    return false;
  };
  if (!initialized_)
    return refuse("Initialize() the simulation from its scene before loading a checkpoint");
  // From here on the state is being overwritten: a refusal leaves the simulation unusable
  // (Run() then reports that it is not initialised) rather than half restored.
  initialized_ = false;
  Archive a = Archive::ForReading(payload);
  try {
    SerializeState(a, may_differ);
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  if (!a.ok()) return refuse("the payload ends before the state is complete");
  if (a.remaining())
    return refuse(std::to_string(a.remaining()) + " bytes left over after the state");
  std::string why;
  if (!CheckRestoredState(&why)) return refuse(why);
  PlaceWalls(time_s_);
  WallRemovedDuringStep(time_s_);
  initialized_ = true;
  return true;
}

}  // namespace demcal::core
