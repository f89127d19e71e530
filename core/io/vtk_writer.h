#pragma once
// Legacy-VTK particle snapshots for ParaView. One file per snapshot: POLYDATA with one point and
// one vertex cell per sphere, the snapshot time as field data (TIME), and point data
//   radius_m, diameter_m (double), velocity_m_s, angular_velocity_rad_s (3-vectors, double),
//   species (int, index into the scene's species), id (int; stable sphere id),
//   body_id (int; the sphere's own id for a free sphere, its clump's id for a clump member).
// Every sphere is written, clump members included, so ParaView shows clumps at their true shape.
// Points are written in id order, so a point index refers to the same particle in every file.
// Binary files follow the legacy format's big-endian convention. VtkSeries collects the files of
// a run and writes the ParaView ".vtk.series" index (file names and simulated times), which
// ParaView opens as one time-dependent dataset.
//
// Thread-safety: free functions with no shared state; a VtkSeries must not be shared.
//
// Usage:
//   std::string error;
//   if (!WriteParticlesVtk("out/p_0.vtk", sim.particles(), sim.time_s(), {}, &error)) ...
#include <string>
#include <vector>

#include "core/bodies/clumps.h"
#include "core/bodies/particles.h"

namespace demcal::core::io {

struct VtkOptions {
  enum class Encoding { kAscii, kBinary };
  Encoding encoding = Encoding::kBinary;
};

// Parses "ascii" | "binary"; returns false for anything else.
bool ParseVtkEncoding(const std::string& name, VtkOptions::Encoding* encoding);

// Writes one snapshot of the spheres (`clumps`, if any, supplies the members' body ids). Returns
// false and explains in `error` if the file cannot be written.
bool WriteParticlesVtk(const std::string& path, const Particles& particles, double time_s,
                       const VtkOptions& options, std::string* error,
                       const Clumps* clumps = nullptr);

// The snapshots of one run and their ParaView series index.
class VtkSeries {
 public:
  struct Entry {
    std::string file_name;  // relative to the directory of the .series file
    double time_s = 0;
  };
  // `directory` receives the snapshots "<prefix>_NNNNNN.vtk" and "<prefix>.vtk.series".
  VtkSeries(std::string directory, std::string prefix, VtkOptions options);

  // Continues the series of an earlier run (a restart into the same directory): `earlier` are
  // its first snapshots, so the next Write is numbered after them. Rewrites the index.
  bool Resume(std::vector<Entry> earlier, std::string* error);
  // Writes the next snapshot and rewrites the series index (so it is valid after a crash).
  bool Write(const Particles& particles, double time_s, std::string* error,
             const Clumps* clumps = nullptr);
  const std::vector<Entry>& entries() const { return entries_; }
  std::string SeriesPath() const;

 private:
  bool WriteIndex(std::string* error) const;

  std::string directory_;
  std::string prefix_;
  VtkOptions options_;
  std::vector<Entry> entries_;
};

}  // namespace demcal::core::io
