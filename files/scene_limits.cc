#include "files/scene_limits.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/insertion/factory.h"

namespace demcal::workflow {
namespace {

double PhysicalMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

double SpheresPerBody(const core::Species& s) {
  return s.clump_shape.empty() ? 1.0 : static_cast<double>(s.clump_shape.size());
}

std::string Gibibytes(double bytes) {
  std::ostringstream os;
  os.precision(3);
  os << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return os.str();
}

}  // namespace

double EstimatedSpheres(const core::Scene& scene) {
  double spheres = 0;
  for (const core::ParticleSpec& p : scene.particles)
    spheres += SpheresPerBody(scene.species[p.species]);
  for (const core::FillSpec& f : scene.fills)
    spheres += static_cast<double>(f.count) * SpheresPerBody(scene.species[f.species]);
  const double duration = scene.time.duration_s;
  for (const core::FactorySpec& f : scene.factories) {
    const double active = std::max(0.0, std::min(f.end_s, duration) - f.start_s);
    const double mass = std::min(f.total_mass_kg, f.mass_rate_kg_s * active);
    // Mass fraction w_k of species k holds w_k M / (ρ_k V̄_k) bodies.
    for (size_t k = 0; k < f.species.size(); ++k) {
      const core::Species& s = scene.species[f.species[k]];
      const double body_mass = scene.materials[s.material].density_kg_m3 * s.size.MeanVolume();
      if (body_mass > 0) spheres += f.mass_fractions[k] * mass / body_mass * SpheresPerBody(s);
    }
  }
  return spheres;
}

bool CheckSceneLimits(const SceneFile& file, std::string* error, double memory_bytes) {
  const core::Scene& scene = file.scene;
  std::ostringstream os;
  const double dt = core::TimeStep(scene);
  const double steps = scene.time.duration_s / dt;
  if (!(dt > 0) || !std::isfinite(steps) || steps > kMaxStepsPerRun) {
    os << "field 'time.duration_s' = " << scene.time.duration_s << " s is " << steps
       << " steps of the time step " << dt << " s; allowed: at most " << kMaxStepsPerRun
       << " steps per run (check the units of the duration, the time step and the diameters)";
  }
  for (size_t i = 0; i < scene.factories.size() && os.str().empty(); ++i) {
    const core::FactorySpec& f = scene.factories[i];
    const double interval =
        core::ParticleFactory::BatchInterval(f, core::Norm(scene.gravity_m_s2));
    const std::string name = "factories[" + std::to_string(i) + "]";
    if (f.batch_interval_s > 0 && f.batch_interval_s < dt)
      os << "field '" << name << ".batch_interval_s' = " << f.batch_interval_s
         << " s is shorter than the time step " << dt
         << " s; allowed: 0 (automatic) or >= the time step";
    else if (!(interval >= dt))
      os << "field '" << name << ".region' gives an automatic batch interval of " << interval
         << " s (the fall time through the region), shorter than the time step " << dt
         << " s; make the region taller or set batch_interval_s >= the time step";
  }
  const double interval = file.output.vtk_interval_s;
  if (os.str().empty() && interval > 0) {
    const double snapshots = scene.time.duration_s / std::max(interval, dt) + 2;
    if (snapshots > kMaxSnapshotsPerRun)
      os << "field 'output.vtk_interval_s' = " << interval << " s gives " << snapshots
         << " snapshots over time.duration_s = " << scene.time.duration_s
         << " s; allowed: at most " << kMaxSnapshotsPerRun
         << " snapshots per run (a longer interval)";
  }
  if (os.str().empty()) {
    const double available = memory_bytes > 0 ? memory_bytes : PhysicalMemoryBytes();
    const double spheres = EstimatedSpheres(scene);
    const double needed = spheres * kBytesPerSphere;
    if (available > 0 && needed > available)
      os << "the scene would hold about " << spheres << " spheres (particles, fills and "
         << "factories over time.duration_s) and need about " << Gibibytes(needed)
         << " of memory (" << kBytesPerSphere << " bytes a sphere); allowed: at most this "
         << "machine's " << Gibibytes(available)
         << "; lower fills[].count, the factories' mass or the duration";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

}  // namespace demcal::workflow
