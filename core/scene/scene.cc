#include "core/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "core/bodies/contact_multiplicity.h"
#include "core/bodies/unit_clump.h"
#include "core/contact/normal_model.h"

namespace demcal::core {

int Scene::MaterialIndex(const std::string& name) const {
  for (size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

int Scene::SpeciesIndex(const std::string& name) const {
  for (size_t i = 0; i < species.size(); ++i)
    if (species[i].name == name) return static_cast<int>(i);
  return -1;
}

double Scene::MaxDiameter() const {
  double d = 0;
  for (const Species& s : species) d = std::max(d, s.size.MaxDiameter());
  for (const ParticleSpec& p : particles) d = std::max(d, p.diameter_m);
  return d;
}

double Scene::MinDiameter() const {
  double d = std::numeric_limits<double>::infinity();
  for (const Species& s : species) d = std::min(d, s.size.MinDiameter());
  for (const ParticleSpec& p : particles)
    if (p.diameter_m > 0) d = std::min(d, p.diameter_m);
  return d;
}

double MaxAdhesiveBreakGap(const Scene& scene) {
  const size_t n = scene.materials.size();
  if (scene.pair_parameters.size() != n * n) return 0;
  const InteractionTable table(scene.materials, scene.pair_parameters);
  const double r_max = 0.5 * scene.MaxDiameter();
  return std::visit(
      [&](const auto& law) {
        double gap = 0;
        for (size_t i = 0; i < n; ++i)
          for (size_t j = 0; j < n; ++j) gap = std::max(gap, law.BreakGap(r_max, table.Get(i, j)));
        return gap;
      },
      SelectNormalModel(scene.pair_parameters));
}

double NeighbourSkin(const Scene& scene) {
  if (scene.skin_m > 0) return scene.skin_m;
  return std::max(0.25 * scene.MinDiameter(), 2.5 * MaxAdhesiveBreakGap(scene));
}

namespace {
// Rayleigh time of one sphere (LIGGGHTS fix_check_timestep_gran; docs/physics.md §1.5).
double SphereRayleighTime(const Material& m, double radius_m) {
  return std::numbers::pi * radius_m * std::sqrt(m.density_kg_m3 / m.ShearModulus()) /
         (0.1631 * m.poisson_ratio + 0.8766);
}

// The radius whose Rayleigh time a species' grain takes, per unit of its size-distribution
// diameter: 1/2 for a sphere; for a clump, whose size is the equivalent-volume diameter, the
// smallest member sphere's radius at unit size (UnitDiameterClumpMembers, as the engine places
// it) times ClumpStepFactor, which shortens the step where members nearly coincide
// (core/bodies/contact_multiplicity.h). A shape that does not build leaves 1/2: validation
// reports it.
double StepRadiusPerDiameter(const Species& sp) {
  if (sp.clump_shape.empty()) return 0.5;
  std::vector<ClumpSphere> members;
  std::string ignored;  // a shape that makes no clump is refused where the scene is checked
  if (!UnitDiameterClumpMembers(sp.clump_shape, &members, &ignored)) return 0.5;
  double smallest = std::numeric_limits<double>::infinity();
  for (const ClumpSphere& m : members) smallest = std::min(smallest, m.radius_m);
  const double unit_volume_m3 = std::numbers::pi / 6;  // the union at unit equivalent diameter
  return smallest * ClumpStepFactor(members, unit_volume_m3);
}
}  // namespace

// Over every sphere that touches, clump members included, as LIGGGHTS' check does: a member
// smaller than its grain's equivalent sphere rings faster, and with the grain's size as the
// scale a compact chain (members close together, several in one contact) ran unstable; members
// that nearly coincide shorten it further (StepRadiusPerDiameter).
double RayleighTime(const Scene& scene) {
  std::vector<double> radius_per_diameter;  // per species; a clump's costs a mass integration
  for (const Species& sp : scene.species) radius_per_diameter.push_back(StepRadiusPerDiameter(sp));
  double t = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < scene.species.size(); ++i)
    t = std::min(t, SphereRayleighTime(scene.materials[scene.species[i].material],
                                       radius_per_diameter[i] * scene.species[i].size.MinDiameter()));
  for (const ParticleSpec& p : scene.particles)
    if (p.diameter_m > 0)
      t = std::min(t, SphereRayleighTime(scene.materials[scene.species[p.species].material],
                                         radius_per_diameter[p.species] * p.diameter_m));
  return t;
}

double TimeStep(const Scene& scene) {
  return scene.time.timestep_s > 0 ? scene.time.timestep_s
                                   : scene.time.rayleigh_fraction * RayleighTime(scene);
}

}  // namespace demcal::core
