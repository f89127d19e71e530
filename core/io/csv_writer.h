#pragma once
// CSV tables of the particle state, SI units named in the column headers. Rows in id order.
// Numbers use the shortest decimal form that reads back to the same double, so a table reloads
// bit-exactly. `species` is the index into the scene's species list.
//
// Spheres (every sphere, clump members included):
//   id,species,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,wy_rad_s,wz_rad_s,diameter_m,mass_kg,
//   body_id
// mass_kg is the mass of the body the sphere moves with (for a clump member, the whole clump);
// body_id is the sphere's own id for a free sphere and its clump's id for a member.
//
// Clumps (rigid bodies; position = centre of mass, q = orientation body → space, w x y z):
//   id,species,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,wy_rad_s,wz_rad_s,qw,qx,qy,qz,mass_kg,
//   members
//
// Thread-safety: no shared state.
//
// Usage:
//   std::string error;
//   if (!WriteParticlesCsv("out/final_particles.csv", sim.particles(), &error)) ...
#include <string>
#include <vector>

#include "core/bodies/clumps.h"
#include "core/bodies/particles.h"

namespace demcal::core::io {

// The column names, in order, of the two tables.
const std::vector<std::string>& ParticleCsvColumns();
const std::vector<std::string>& ClumpCsvColumns();

// `clumps` (may be null) supplies the body ids of clump members.
bool WriteParticlesCsv(const std::string& path, const Particles& particles, std::string* error,
                       const Clumps* clumps = nullptr);
bool WriteClumpsCsv(const std::string& path, const Clumps& clumps, std::string* error);

}  // namespace demcal::core::io
