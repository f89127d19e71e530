#include "workflow/export/export_scene.h"

#include <sstream>

#include "calibrate/pair_property.h"
#include "experiments/aor/aor_experiment.h"
#include "experiments/aor/aor_section.h"
#include "experiments/discharge/discharge_experiment.h"
#include "experiments/discharge/discharge_section.h"
#include "experiments/discharge/hopper_fill.h"
#include "objectives/common/glued_base.h"

namespace demcal::workflow {
namespace {

bool DischargeRunOf(const ExperimentFile& file, const core::Scene& model, ExportRun* out,
                    std::string* error) {
  objectives::DischargeSettings settings;
  std::string why;
  if (!ParseDischargeSection(file.section, file.source, model, &settings, error)) return false;
  if (!settings.IsValid(model, &why)) {
    *error = file.source + ": " + why;
    return false;
  }
  out->scene = objectives::BuildDischargeScene(model, settings, file.seed);
  for (core::Wall& w : out->scene.walls) {
    if (w.name != "gate") continue;
    w.velocity_m_s = {};  // taken away instead (see the header)
    out->open_wall = w.name;
  }
  if (out->open_wall.empty()) {
    *error = file.source + ": the discharge scene has no wall named 'gate'";
    return false;
  }
  if (!out->scene.IsValid(&why)) {
    *error = file.source + ": the discharge scene is invalid: " + why;
    return false;
  }
  out->open_at_s = settings.gate_open_s;
  out->settle = settings.gate_open_s <= 0;
  out->settle_criteria = settings.settle;
  out->settle_criteria.feed_end_s = objectives::FillEndS(model, settings);
  out->after_open_max_s = settings.max_discharge_s;
  out->empty_above_z_m = 0;  // the orifice plane
  return true;
}

}  // namespace

bool ExportRunOf(const ExperimentFile& file, const objectives::Fidelity& fidelity, ExportRun* out,
                 std::string* error) {
  *out = {};
  std::string why;
  if (!fidelity.IsValid(&why)) {
    *error = file.source + ": fidelity '" + fidelity.name + "': " + why;
    return false;
  }
  core::Scene model = file.model;
  objectives::ApplyFidelity(fidelity, &model);
  if (file.experiment == "discharge") return DischargeRunOf(file, model, out, error);
  if (file.experiment != "aor") {
    *error = file.source + ": experiment '" + file.experiment + "' is not exported: its " +
             "outputs need grains tracked between steps, which a LIGGGHTS deck cannot say; aor " +
             "and discharge are exported";
    return false;
  }
  objectives::AorSettings settings;
  if (!ParseAorSection(file.section, file.source, model, &settings, error)) return false;
  if (!settings.IsValid(model, &why)) {
    *error = file.source + ": " + why;
    return false;
  }
  int64_t fixed = 0;
  out->scene = objectives::BuildAorScene(model, settings, file.seed, &fixed);
  if (!out->scene.IsValid(&why)) {
    *error = file.source + ": the aor scene is invalid: " + why;
    return false;
  }
  out->settle = true;
  out->settle_criteria = settings.settle;
  out->settle_criteria.feed_end_s = settings.feed.EndS();
  if (settings.glued_base) {
    objectives::GluedBaseSpec base = objectives::GluedBaseOfFeed(model, settings.feed, file.seed);
    out->base_top_m = objectives::GluedBaseTop(base);
  }
  return true;
}

bool ApplyCalibratedParams(const nlohmann::json& params, const std::string& source,
                           core::Scene* model, std::string* error) {
  if (!params.is_object() || params.value("format", "") != "demcal-params/1") {
    *error = source + ": field 'format' must be \"demcal-params/1\" (a calibration's " +
             "calibrated_params.json)";
    return false;
  }
  const auto pairs = params.find("interactions_pairs");
  if (pairs == params.end() || !pairs->is_array()) {
    *error = source + ": field 'interactions_pairs' must be an array";
    return false;
  }
  for (size_t k = 0; k < pairs->size(); ++k) {
    const nlohmann::json& p = (*pairs)[k];
    const std::string where = source + ": field 'interactions_pairs[" + std::to_string(k) + "]";
    const auto names = p.find("materials");
    if (!p.is_object() || names == p.end() || !names->is_array() || names->size() != 2 ||
        !(*names)[0].is_string() || !(*names)[1].is_string()) {
      *error = where + ".materials' must name two materials";
      return false;
    }
    const int i = model->MaterialIndex((*names)[0].get<std::string>());
    const int j = model->MaterialIndex((*names)[1].get<std::string>());
    if (i < 0 || j < 0) {
      *error = where + ".materials' names a material the experiment file does not define";
      return false;
    }
    for (auto it = p.begin(); it != p.end(); ++it) {
      if (it.key() == "materials") continue;
      calibrate::PairProperty property;
      if (!calibrate::PairPropertyFromKey(it.key(), &property)) {
        *error = where + "." + it.key() + "' is not a pair property (sliding_friction, " +
                 "rolling_friction, restitution, interfacial_energy_J_m2, " +
                 "cohesion_energy_density_J_m3)";
        return false;
      }
      const double max = calibrate::PairPropertyMax(property);
      if (!it->is_number() || !(it->get<double>() >= 0 && it->get<double>() <= max)) {
        std::ostringstream os;
        os << where << "." << it.key() << "' must be a number in [0, " << max << "]";
        *error = os.str();
        return false;
      }
      calibrate::SetPairProperty(property, i, j, it->get<double>(), model);
    }
  }
  return true;
}

}  // namespace demcal::workflow
