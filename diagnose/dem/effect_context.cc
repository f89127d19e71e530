#include "diagnose/dem/effect_context.h"

#include <algorithm>
#include <set>

#include "calibrate/liggghts_export.h"

namespace demcal::diagnose {
namespace {

int SubjectSpecies(const core::Scene& model, const std::string& material) {
  int found = -1;
  for (size_t s = 0; s < model.species.size(); ++s) {
    if (model.materials[model.species[s].material].name != material) continue;
    if (model.species[s].name == material) return static_cast<int>(s);
    if (found < 0) found = static_cast<int>(s);
  }
  return found;
}

// The base model's values of what the signed effects shift (effect.h).
void BaseValues(const core::Scene& model, int s, EffectContext* out) {
  const int n = static_cast<int>(model.materials.size());
  const int m = model.species[s].material;
  if (static_cast<int>(model.pair_parameters.size()) == n * n) {
    const core::PairParameters& self = model.pair_parameters[m * n + m];
    out->sliding_friction = self.sliding_friction;
    out->rolling_friction = self.rolling_friction;
    out->interfacial_energy = self.interfacial_energy_J_m2;
    out->cohesion_energy_density = self.cohesion_energy_density_J_m3;
    out->wall_friction = 0;
    bool first = true;
    for (const std::string& wall : out->wall_materials) {
      const double mu = model.pair_parameters[m * n + model.MaterialIndex(wall)].sliding_friction;
      out->wall_friction = first ? mu : std::min(out->wall_friction, mu);
      first = false;
    }
  }
  const core::Material& own = model.materials[m];
  out->self_effective_youngs_Pa =
      own.youngs_modulus_Pa / (2 * (1 - own.poisson_ratio * own.poisson_ratio));
  out->self_effective_radius_m = 0.5 * calibrate::ContactUseOf(model).mean_radius_m[m];
  const core::SizeDistribution& size = model.species[s].size;
  using Kind = core::SizeDistribution::Kind;
  out->relative_width = 0;
  if (size.kind == Kind::kUniform && size.max_diameter_m + size.min_diameter_m > 0)
    out->relative_width = 2 * (size.max_diameter_m - size.min_diameter_m) /
                          (size.max_diameter_m + size.min_diameter_m);
}

}  // namespace

bool MakeEffectContext(const workflow::StudyFile& study, const std::string& species,
                       EffectContext* out, std::string* error) {
  const core::Scene& model = study.experiment().model;
  int s = -1;
  if (!species.empty()) {
    s = model.SpeciesIndex(species);
    if (s < 0)
      return *error = "--species: the study's first experiment has no species '" + species + "'",
             false;
  } else if (!study.parameter_materials.empty()) {
    s = SubjectSpecies(model, study.parameter_materials.front().first);
  }
  if (s < 0 && !model.species.empty()) s = 0;
  if (s < 0) return *error = study.source + ": the first experiment has no species", false;
  out->species = model.species[s].name;
  out->material = model.materials[model.species[s].material].name;
  std::set<int> particle_materials;
  for (const core::Species& sp : model.species) particle_materials.insert(sp.material);
  out->wall_materials.clear();
  for (size_t m = 0; m < model.materials.size(); ++m)
    if (!particle_materials.count(static_cast<int>(m)))
      out->wall_materials.push_back(model.materials[m].name);
  out->coating_column.clear();
  out->coating_max = 0;
  for (const workflow::StudyTarget& t : study.targets)
    for (const auto& [column, cell] : t.condition) {
      double value = 0;
      if (column.rfind("coating", 0) != 0 || !calibrate::ParseConditionNumber(cell, &value))
        continue;
      if (out->coating_column.empty() || out->coating_column == column) {
        out->coating_column = column;
        out->coating_max = std::max(out->coating_max, value);
      }
    }
  if (out->coating_max <= 0) out->coating_column.clear();
  BaseValues(model, s, out);
  return true;
}

}  // namespace demcal::diagnose
