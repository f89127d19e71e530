#include "core/scene/scene_fingerprint.h"

#include <algorithm>
#include <variant>

#include "core/math/fnv1a.h"

namespace demcal::core {
namespace {

void AddSize(const SizeDistribution& s, Fnv1a64& h) {
  h.Field(static_cast<int>(s.kind)), h.Field(s.diameter_m), h.Field(s.min_diameter_m);
  h.Field(s.max_diameter_m), h.Field(s.table_diameter_m.size());
  for (size_t k = 0; k < s.table_diameter_m.size(); ++k) h.Field(s.table_diameter_m[k]);
  for (double f : s.table_number_fraction) h.Field(f);
}

void AddShape(const WallShape& shape, Fnv1a64& h) {
  h.Field(shape.index());
  if (const auto* p = std::get_if<PlaneSurface>(&shape)) {
    h.Field(p->point_m), h.Field(p->normal);
  } else if (const auto* c = std::get_if<CylinderSurface>(&shape)) {
    h.Field(c->axis_point_m), h.Field(c->axis), h.Field(c->radius_m), h.Field(c->axial_min_m);
    h.Field(c->axial_max_m), h.Field(c->inside);
  } else if (const auto* k = std::get_if<ConeFrustumSurface>(&shape)) {
    h.Field(k->axis_point_m), h.Field(k->axis), h.Field(k->height0_m), h.Field(k->radius0_m);
    h.Field(k->height1_m), h.Field(k->radius1_m), h.Field(k->inside);
  } else {
    const MeshRef& m = std::get<MeshRef>(shape);
    h.Field(m.offset_m);
    h.Field(m.mesh ? m.mesh->NumVertices() : 0), h.Field(m.mesh ? m.mesh->NumTriangles() : 0);
    for (size_t v = 0; m.mesh && v < m.mesh->NumVertices(); ++v)
      h.Field(m.mesh->Vertex(static_cast<int32_t>(v)));
  }
}

void AddRegion(const InsertionRegion& r, Fnv1a64& h) {
  h.Field(static_cast<int>(r.shape)), h.Field(r.min_m), h.Field(r.max_m);
  h.Field(r.axis_point_m), h.Field(r.radius_m);
}

template <class AddAll>
FingerprintPart Part(const char* name, AddAll&& add) {
  Fnv1a64 h;
  add(h);
  return {name, h.digest()};
}

}  // namespace

std::vector<FingerprintPart> SceneFingerprint(const Scene& s, double timestep_s, double skin_m) {
  std::vector<FingerprintPart> parts;
  parts.push_back(Part("materials", [&](Fnv1a64& h) {
    for (const Material& m : s.materials)
      h.Text(m.name), h.Field(m.youngs_modulus_Pa), h.Field(m.poisson_ratio), h.Field(m.density_kg_m3);
  }));
  parts.push_back(Part("species", [&](Fnv1a64& h) {
    for (const Species& sp : s.species) {
      h.Text(sp.name), h.Field(sp.material), AddSize(sp.size, h), h.Field(sp.clump_shape.size());
      for (const ShapeSphere& c : sp.clump_shape) h.Field(c.centre), h.Field(c.radius);
    }
  }));
  parts.push_back(Part("contact parameters", [&](Fnv1a64& h) {
    for (const PairParameters& p : s.pair_parameters) {
      h.Field(p.sliding_friction), h.Field(p.rolling_friction), h.Field(p.restitution),
          h.Field(p.interfacial_energy_J_m2);
      // Hashed only when set: a scene without sjkr cohesion hashes as one that cannot have it,
      // so the checkpoints and journals of such scenes keep their keys.
      if (p.cohesion_energy_density_J_m3 != 0)
        h.Text("sjkr"), h.Field(p.cohesion_energy_density_J_m3);
    }
    h.Text(s.rolling.name), h.Field(s.rolling.epsd_damping_ratio), h.Text(s.rolling.jkr_rolling_load);
  }));
  parts.push_back(Part("walls", [&](Fnv1a64& h) {
    for (const Wall& w : s.walls)
      h.Text(w.name), h.Field(w.material), AddShape(w.shape, h), h.Field(w.load_point_m),
          h.Field(w.shell);
  }));
  parts.push_back(Part("wall motion", [&](Fnv1a64& h) {
    for (const Wall& w : s.walls)
      h.Field(w.velocity_m_s), h.Field(w.motion_start_s), h.Field(w.motion_end_s),
          h.Field(w.remove_at_s);
  }));
  // The checkpoint carries one tally per sink: another sink list is another scene.
  parts.push_back(Part("sinks", [&](Fnv1a64& h) {
    for (const SinkSpec& k : s.sinks)
      h.Text(k.name), h.Field(static_cast<int>(k.shape)), h.Field(k.point_m), h.Field(k.normal),
          h.Field(k.min_m), h.Field(k.max_m);
  }));
  parts.push_back(Part("domain", [&](Fnv1a64& h) {
    h.Field(s.domain_min_m), h.Field(s.domain_max_m);
    for (bool p : s.periodic) h.Field(p);
  }));
  parts.push_back(Part("gravity", [&](Fnv1a64& h) { h.Field(s.gravity_m_s2); }));
  parts.push_back(Part("initial particles", [&](Fnv1a64& h) {
    for (const ParticleSpec& p : s.particles) {
      h.Field(p.species), h.Field(p.position_m), h.Field(p.velocity_m_s);
      h.Field(p.angular_velocity_rad_s), h.Field(p.diameter_m), h.Field(p.fixed);
      h.Field(p.orientation.w), h.Field(p.orientation.x), h.Field(p.orientation.y);
      h.Field(p.orientation.z);
    }
    h.Field(s.particles.size());
    for (const FillSpec& f : s.fills)
      h.Field(f.species), AddRegion(f.region, h), h.Field(f.count), h.Field(f.velocity_m_s);
  }));
  parts.push_back(Part("factories", [&](Fnv1a64& h) {
    for (const FactorySpec& f : s.factories) {
      h.Text(f.name), AddRegion(f.region, h);
      h.Field(f.species.size());
      for (size_t k = 0; k < f.species.size(); ++k) h.Field(f.species[k]);
      for (double x : f.mass_fractions) h.Field(x);
      h.Field(f.mass_rate_kg_s), h.Field(f.start_s), h.Field(f.end_s), h.Field(f.total_mass_kg);
      h.Field(f.velocity_m_s), h.Field(f.batch_interval_s), h.Field(f.region_velocity_m_s);
      h.Field(f.follow_heap_clearance_m), h.Field(f.settled_speed_m_s);
    }
  }));
  parts.push_back(Part("seed", [&](Fnv1a64& h) { h.Field(s.seed); }));
  parts.push_back(Part("time step", [&](Fnv1a64& h) { h.Field(timestep_s); }));
  parts.push_back(Part("neighbour skin", [&](Fnv1a64& h) { h.Field(skin_m); }));
  return parts;
}

std::string DifferingParts(const std::vector<FingerprintPart>& stored,
                           const std::vector<FingerprintPart>& current,
                           const std::vector<std::string>& ignore) {
  std::string out;
  std::vector<std::string> noted(ignore);
  auto note = [&](const std::string& name) {
    if (std::find(noted.begin(), noted.end(), name) != noted.end()) return;
    noted.push_back(name);
    out += (out.empty() ? "" : ", ") + name;
  };
  for (const FingerprintPart& c : current) {
    bool same = false;
    for (const FingerprintPart& s : stored) same = same || (s.name == c.name && s.digest == c.digest);
    if (!same) note(c.name);
  }
  for (const FingerprintPart& s : stored) {
    bool known = false;
    for (const FingerprintPart& c : current) known = known || s.name == c.name;
    if (!known) note(s.name);
  }
  return out;
}

}  // namespace demcal::core
