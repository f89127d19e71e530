#pragma once
// CSV particle table: one row per sphere in id order, SI units named in the column headers:
//   id,species,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,wy_rad_s,wz_rad_s,diameter_m,mass_kg
// `species` is the index into the scene's species list. Numbers use the shortest decimal form
// that reads back to the same double, so a table reloads bit-exactly.
//
// Thread-safety: no shared state.
//
// Usage:
//   std::string error;
//   if (!WriteParticlesCsv("out/final_particles.csv", sim.particles(), &error)) ...
#include <string>
#include <vector>

#include "core/particles.h"

namespace demcal::core::io {

// The header line (without newline); the column order of WriteParticlesCsv.
const std::vector<std::string>& ParticleCsvColumns();

bool WriteParticlesCsv(const std::string& path, const Particles& particles, std::string* error);

}  // namespace demcal::core::io
