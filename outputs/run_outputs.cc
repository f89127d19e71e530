#include "outputs/run_outputs.h"

#include <cmath>
#include <filesystem>
#include <system_error>

#include "core/io/csv_writer.h"
#include "core/io/input_file.h"

namespace demcal::workflow {
namespace {
constexpr const char* kVtkDir = "vtk";
constexpr const char* kVtkPrefix = "particles";
constexpr const char* kSceneCopy = "scene.json";
// At most 100000 snapshots a run, each a line of under 100 bytes in the index.
constexpr size_t kMaxSeriesIndexBytes = size_t{64} << 20;
constexpr const char* kCheckpoint = "checkpoint.bin";

// The snapshots of an earlier run listed in a ParaView series index, up to `time_s` and only
// while their files exist (a run killed while writing leaves no gaps in the numbering).
bool ReadSeriesUpTo(const std::filesystem::path& index, double time_s,
                    std::vector<core::io::VtkSeries::Entry>* entries, std::string* error) {
  std::string text;
  if (!core::io::ReadRegularFile(index.string(), "snapshot series index", kMaxSeriesIndexBytes,
                                 {}, &text, error)) {
    if (error) *error = "cannot continue the snapshot series: " + *error;
    return false;
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    for (const nlohmann::json& f : j.at("files")) {
      core::io::VtkSeries::Entry e{f.at("name").get<std::string>(), f.at("time").get<double>()};
      if (e.time_s > time_s || !std::filesystem::exists(index.parent_path() / e.file_name)) break;
      entries->push_back(std::move(e));
    }
  } catch (const nlohmann::json::exception& e) {
    if (error) *error = "cannot continue the snapshot series '" + index.string() + "': " + e.what();
    return false;
  }
  return true;
}
}  // namespace

RunOutputs::RunOutputs(std::string directory, OutputSettings settings)
    : directory_(std::move(directory)),
      settings_(settings),
      series_(directory_ + "/" + kVtkDir, kVtkPrefix, settings.vtk) {}

bool RunOutputs::Prepare(std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(directory_) / kVtkDir, ec);
  if (ec) {
    if (error) *error = "cannot create output directory '" + directory_ + "': " + ec.message();
    return false;
  }
  return true;
}

bool RunOutputs::CopyScene(const std::string& scene_path, std::string* error) {
  namespace fs = std::filesystem;
  const fs::path target = fs::path(directory_) / kSceneCopy;
  std::error_code ec;
  // copy_file writes through a link at the target: a link found there is removed first (the
  // link itself, never its target), so the copy cannot overwrite a file outside --out.
  if (fs::is_symlink(fs::symlink_status(target, ec))) fs::remove(target, ec);
  ec.clear();
  if (!fs::equivalent(scene_path, target, ec))
    fs::copy_file(scene_path, target, fs::copy_options::overwrite_existing, ec);
  if (ec) {
    if (error) *error = "cannot copy the scene to '" + target.string() + "': " + ec.message();
    return false;
  }
  scene_copied_ = true;
  return true;
}

bool RunOutputs::ResumeFrom(const core::Simulation& sim, std::string* error) {
  const std::filesystem::path index = series_.SeriesPath();
  std::vector<core::io::VtkSeries::Entry> earlier;
  if (std::filesystem::exists(index) && !ReadSeriesUpTo(index, sim.time_s(), &earlier, error))
    return false;
  const bool have_this_time = !earlier.empty() && earlier.back().time_s == sim.time_s();
  if (!series_.Resume(std::move(earlier), error)) return false;
  if (have_this_time) {
    last_snapshot_step_ = sim.steps();
    return true;
  }
  return WriteSnapshot(sim, error);
}

std::string RunOutputs::CheckpointPath() const { return directory_ + "/" + kCheckpoint; }

bool RunOutputs::WriteCheckpoint(const core::Simulation& sim, std::string* error) {
  if (!sim.SaveCheckpoint(CheckpointPath(), error)) return false;  // atomic (temporary + rename)
  checkpoint_time_s_ = sim.time_s();
  return true;
}

int64_t RunOutputs::SnapshotEverySteps(double timestep_s) const {
  if (!(settings_.vtk_interval_s > 0) || !(timestep_s > 0)) return 0;
  return std::max<int64_t>(1, std::llround(settings_.vtk_interval_s / timestep_s));
}

bool RunOutputs::WriteSnapshot(const core::Simulation& sim, std::string* error) {
  const core::Clumps& clumps = sim.system().clumps;
  if (!series_.Write(sim.particles(), sim.time_s(), error, &clumps)) return false;
  last_snapshot_step_ = sim.steps();
  return true;
}

bool RunOutputs::WriteFinal(const core::Simulation& sim, std::string* error) {
  if (last_snapshot_step_ != sim.steps() && !WriteSnapshot(sim, error)) return false;
  const core::Clumps& clumps = sim.system().clumps;
  if (!core::io::WriteParticlesCsv(CsvPath(), sim.particles(), error, &clumps)) return false;
  csv_written_ = true;
  if (clumps.Size() > 0) {
    if (!core::io::WriteClumpsCsv(ClumpCsvPath(), clumps, error)) return false;
    clump_csv_written_ = true;
  }
  return true;
}

nlohmann::ordered_json RunOutputs::Describe() const {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  if (scene_copied_) out["scene_copy"] = kSceneCopy;
  if (!series_.entries().empty()) {
    out["vtk_series"] = std::string(kVtkDir) + "/" + kVtkPrefix + ".vtk.series";
    out["vtk_snapshots"] = series_.entries().size();
    out["vtk_format"] =
        settings_.vtk.encoding == core::io::VtkOptions::Encoding::kBinary ? "binary" : "ascii";
  }
  if (csv_written_) out["final_particles_csv"] = "final_particles.csv";
  if (clump_csv_written_) out["final_clumps_csv"] = "final_clumps.csv";
  if (checkpoint_time_s_ >= 0) {
    out["checkpoint"] = kCheckpoint;
    out["checkpoint_time_s"] = checkpoint_time_s_;
  }
  return out;
}

}  // namespace demcal::workflow
