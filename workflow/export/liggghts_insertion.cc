#include "workflow/export/liggghts_insertion.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/bodies/clump_template.h"
#include "workflow/export/liggghts_number.h"

namespace demcal::workflow {
namespace {

// One particle template: a species at one volume-equivalent diameter.
struct SizeClass {
  double diameter_m = 0;
  double number_fraction = 0;  // within its species
};

std::vector<SizeClass> SizeClasses(const core::SizeDistribution& s) {
  using Kind = core::SizeDistribution::Kind;
  if (s.kind == Kind::kFixed) return {{s.diameter_m, 1.0}};
  std::vector<SizeClass> out;
  if (s.kind == Kind::kUniform) {
    const double w = (s.max_diameter_m - s.min_diameter_m) / kSizeClasses;
    for (int k = 0; k < kSizeClasses; ++k)
      out.push_back({s.min_diameter_m + (k + 0.5) * w, 1.0 / kSizeClasses});
    return out;
  }
  for (size_t k = 0; k < s.table_diameter_m.size(); ++k)
    out.push_back({s.table_diameter_m[k], s.table_number_fraction[k]});
  return out;
}

// Distinct primes LIGGGHTS wants as seeds (> 10000), from the scene seed and a running index.
class Seeds {
 public:
  explicit Seeds(uint64_t seed) : next_(10007 + static_cast<int64_t>(seed % 100000) * 2) {}
  int64_t Next() {
    for (++next_;; ++next_)
      if (IsPrime(next_)) return next_;
  }

 private:
  static bool IsPrime(int64_t n) {
    for (int64_t d = 2; d * d <= n; ++d)
      if (n % d == 0) return false;
    return n > 1;
  }
  int64_t next_;
};

std::string RegionCommand(const std::string& id, const core::InsertionRegion& r) {
  std::ostringstream out;
  out << "region " << id;
  if (r.shape == core::InsertionRegion::Shape::kBox)
    out << " block " << Num(r.min_m.x) << " " << Num(r.max_m.x) << " " << Num(r.min_m.y) << " "
        << Num(r.max_m.y) << " " << Num(r.min_m.z) << " " << Num(r.max_m.z);
  else
    out << " cylinder z " << Num(r.axis_point_m.x) << " " << Num(r.axis_point_m.y) << " "
        << Num(r.radius_m) << " " << Num(r.min_m.z) << " " << Num(r.max_m.z);
  return out.str() + " units box\n";
}

// The templates of species s ("t<s>_<k>"), their mass and number fractions.
struct SpeciesTemplates {
  std::vector<std::string> ids;
  std::vector<double> number_fraction;
  double mean_mass_kg = 0;
};

bool WriteTemplates(const core::Scene& scene, size_t s, Seeds& seeds, int* multisphere_count,
                    std::ostream& out, SpeciesTemplates* t, std::string* error) {
  const core::Species& sp = scene.species[s];
  const core::Material& mat = scene.materials[sp.material];
  std::vector<core::ClumpSphere> unit;
  if (!sp.clump_shape.empty()) {
    for (const core::ShapeSphere& m : sp.clump_shape) unit.push_back({m.centre, m.radius});
    core::ClumpTemplate raw;
    std::string why;
    if (!core::BuildClumpTemplate(unit, 1.0, {}, &raw, &why)) {
      *error = "species '" + sp.name + "': " + why;
      return false;
    }
    // demcal's scaling (ParticleSystem::SetSpecies): unit volume-equivalent diameter, with
    // the centre of mass at the origin as LIGGGHTS computes it for the template.
    const double k = 1.0 / raw.EquivalentVolumeDiameter();
    unit.clear();
    for (const core::ClumpSphere& m : raw.spheres) unit.push_back({m.centre_m * k, m.radius_m * k});
  }
  const std::vector<SizeClass> classes = SizeClasses(sp.size);
  for (size_t k = 0; k < classes.size(); ++k) {
    const double d = classes[k].diameter_m;
    const std::string id = "t" + std::to_string(s + 1) + "_" + std::to_string(k + 1);
    out << "fix " << id << " flow particletemplate/" << (unit.empty() ? "sphere " : "multisphere ")
        << seeds.Next() << " atom_type " << sp.material + 1 << " density constant "
        << Num(mat.density_kg_m3);
    if (unit.empty()) {
      out << " radius constant " << Num(0.5 * d) << "\n";
    } else {
      out << " nspheres " << unit.size() << " ntry 1000000 spheres";
      for (const core::ClumpSphere& m : unit)
        out << " " << Num(m.centre_m.x * d) << " " << Num(m.centre_m.y * d) << " "
            << Num(m.centre_m.z * d) << " " << Num(m.radius_m * d);
      // LIGGGHTS numbers its multisphere templates ("type", unique per template).
      out << " type " << ++*multisphere_count << "\n";
    }
    t->ids.push_back(id);
    t->number_fraction.push_back(classes[k].number_fraction);
    t->mean_mass_kg +=
        classes[k].number_fraction * mat.density_kg_m3 * std::numbers::pi / 6 * d * d * d;
  }
  return true;
}

// "fix ID all particledistribution/discrete/numberbased SEED N t1 f1 ..." for species with mass
// fractions; the number fraction of a template is ∝ (species mass fraction / species mean
// mass) × its number fraction within the species.
std::string Distribution(const std::string& id, const std::vector<int>& species,
                         const std::vector<double>& mass_fractions,
                         const std::vector<SpeciesTemplates>& templates, Seeds& seeds) {
  std::vector<std::string> ids;
  std::vector<double> numbers;
  double sum = 0;
  for (size_t c = 0; c < species.size(); ++c) {
    const SpeciesTemplates& t = templates[species[c]];
    for (size_t k = 0; k < t.ids.size(); ++k) {
      ids.push_back(t.ids[k]);
      numbers.push_back(mass_fractions[c] / t.mean_mass_kg * t.number_fraction[k]);
      sum += numbers.back();
    }
  }
  std::ostringstream out;
  out << "fix " << id << " flow particledistribution/discrete/numberbased " << seeds.Next() << " "
      << ids.size();
  for (size_t k = 0; k < ids.size(); ++k) out << " " << ids[k] << " " << Num(numbers[k] / sum);
  return out.str() + "\n";
}

std::string DataFile(const core::Scene& scene, int64_t* fixed) {
  std::vector<const core::ParticleSpec*> order;
  for (const core::ParticleSpec& p : scene.particles)
    if (p.fixed) order.push_back(&p);
  *fixed = static_cast<int64_t>(order.size());
  for (const core::ParticleSpec& p : scene.particles)
    if (!p.fixed) order.push_back(&p);
  std::ostringstream out;
  out << "demcal scene particles (ids 1.." << *fixed
      << " fixed); id type diameter density x y z\n\n"
      << order.size() << " atoms\n"
      << scene.materials.size() << " atom types\n\n"
      << Num(scene.domain_min_m.x) << " " << Num(scene.domain_max_m.x) << " xlo xhi\n"
      << Num(scene.domain_min_m.y) << " " << Num(scene.domain_max_m.y) << " ylo yhi\n"
      << Num(scene.domain_min_m.z) << " " << Num(scene.domain_max_m.z) << " zlo zhi\n\nAtoms\n\n";
  for (size_t a = 0; a < order.size(); ++a) {
    const core::ParticleSpec& p = *order[a];
    const core::Species& sp = scene.species[p.species];
    const double d = p.diameter_m > 0 ? p.diameter_m : sp.size.Sample(0.5);
    out << a + 1 << " " << sp.material + 1 << " " << Num(d) << " "
        << Num(scene.materials[sp.material].density_kg_m3) << " " << Num(p.position_m.x) << " "
        << Num(p.position_m.y) << " " << Num(p.position_m.z) << "\n";
  }
  out << "\nVelocities\n\n";
  for (size_t a = 0; a < order.size(); ++a) {
    const core::ParticleSpec& p = *order[a];
    out << a + 1 << " " << Num(p.velocity_m_s.x) << " " << Num(p.velocity_m_s.y) << " "
        << Num(p.velocity_m_s.z) << " " << Num(p.angular_velocity_rad_s.x) << " "
        << Num(p.angular_velocity_rad_s.y) << " " << Num(p.angular_velocity_rad_s.z) << "\n";
  }
  return out.str();
}

int64_t Steps(double time_s, double timestep_s) {
  return std::max<int64_t>(1, std::llround(time_s / timestep_s));
}

}  // namespace

bool LiggghtsParticleCommands(const core::Scene& scene, double timestep_s, LiggghtsParticles* out,
                              std::string* error) {
  *out = {};
  for (size_t k = 0; k < scene.particles.size(); ++k) {
    if (!scene.species[scene.particles[k].species].clump_shape.empty()) {
      *error = "particles[" + std::to_string(k) + "]: a placed clump is not exported (placed " +
               "particles are written as spheres in a read_data file)";
      return false;
    }
  }
  // LIGGGHTS integrates clumps with fix multisphere and single spheres with fix nve/sphere, each
  // on a group; inserted grains all join one group, so one deck moves one kind.
  std::vector<bool> moves(scene.species.size(), false);
  for (const core::FactorySpec& f : scene.factories)
    for (int s : f.species) moves[s] = true;
  for (const core::FillSpec& f : scene.fills) moves[f.species] = true;
  for (const core::ParticleSpec& p : scene.particles)
    if (!p.fixed) moves[p.species] = true;
  bool spheres = false;
  for (size_t s = 0; s < moves.size(); ++s) {
    if (!moves[s]) continue;
    (scene.species[s].clump_shape.empty() ? spheres : out->clumps) = true;
  }
  if (spheres && out->clumps) {
    *error = "the scene moves clumps and single spheres together, which one LIGGGHTS deck " +
             std::string("does not integrate (fix multisphere and fix nve/sphere need separate ") +
             "groups; inserted grains share one)";
    return false;
  }
  if (!scene.particles.empty()) out->data_file = DataFile(scene, &out->fixed);
  out->placed = static_cast<int64_t>(scene.particles.size());
  Seeds seeds(scene.seed);
  std::ostringstream cmd;
  std::vector<SpeciesTemplates> templates(scene.species.size());
  int multisphere_count = 0;
  for (size_t s = 0; s < scene.species.size(); ++s) {
    if (!WriteTemplates(scene, s, seeds, &multisphere_count, cmd, &templates[s], error))
      return false;
  }
  const double g = Norm(scene.gravity_m_s2);
  for (size_t f = 0; f < scene.factories.size(); ++f) {
    const core::FactorySpec& fs = scene.factories[f];
    const std::string name = "factory '" + fs.name + "'";
    if (Norm(fs.region_velocity_m_s) > 0 || fs.follow_heap_clearance_m > 0) {
      *error = name + ": a moving or heap-following insertion region is not exported";
      return false;
    }
    const std::string id = "f" + std::to_string(f + 1);
    cmd << "# " << name << "\n"
        << Distribution(id + "_dist", fs.species, fs.mass_fractions, templates, seeds)
        << RegionCommand(id + "_region", fs.region);
    const double end = std::min(fs.end_s, fs.start_s + fs.total_mass_kg / fs.mass_rate_kg_s);
    const double mass = fs.mass_rate_kg_s * (end - fs.start_s);
    if (!std::isfinite(mass)) {
      *error = name + ": pours without end (no end_s, no total mass); LIGGGHTS needs a mass";
      return false;
    }
    cmd << "fix " << id << " flow insert/rate/region seed " << seeds.Next()
        << " distributiontemplate " << id << "_dist mass " << Num(mass) << " massrate "
        << Num(fs.mass_rate_kg_s) << " insert_every "
        << Steps(core::ParticleFactory::BatchInterval(fs, g), timestep_s);
    if (fs.start_s > 0) cmd << " start " << Steps(fs.start_s, timestep_s);
    cmd << " overlapcheck yes all_in yes vel constant " << Num(fs.velocity_m_s.x) << " "
        << Num(fs.velocity_m_s.y) << " " << Num(fs.velocity_m_s.z) << " region " << id
        << "_region ntry_mc 10000\n";
  }
  for (size_t f = 0; f < scene.fills.size(); ++f) {
    const core::FillSpec& fill = scene.fills[f];
    const std::string id = "fill" + std::to_string(f + 1);
    cmd << "# fills[" << f << "]\n"
        << Distribution(id + "_dist", {fill.species}, {1.0}, templates, seeds)
        << RegionCommand(id + "_region", fill.region) << "fix " << id << " flow insert/pack seed "
        << seeds.Next() << " distributiontemplate " << id
        << "_dist insert_every once overlapcheck yes all_in yes particles_in_region " << fill.count
        << " vel constant " << Num(fill.velocity_m_s.x) << " " << Num(fill.velocity_m_s.y) << " "
        << Num(fill.velocity_m_s.z) << " region " << id << "_region ntry_mc 10000\n";
  }
  out->commands = cmd.str();
  return true;
}

}  // namespace demcal::workflow
