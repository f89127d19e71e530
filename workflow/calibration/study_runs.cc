#include "workflow/calibration/study_runs.h"

#include <filesystem>
#include <sstream>

#include "core/bodies/clump_shapes.h"
#include "core/math/fnv1a.h"
#include "experiments/common/experiment_runner.h"
#include "experiments/experiment_registry.h"
#include "files/json_document.h"

namespace demcal::workflow {
namespace {

// The equal-volume n-sphere chain of the study's ellipsoid on the named species.
bool SetClumpCount(const ClumpCountSearch& search, int n, core::Scene* model, std::string* error) {
  for (core::Species& s : model->species) {
    if (s.name != search.species) continue;
    s.clump_shape.clear();
    if (n == 1) continue;
    core::ShapeApproximation shape;
    if (!core::ApproximateEllipsoid(search.semi_axes, n, &shape, error)) return false;
    for (const core::ClumpSphere& c : shape.spheres) s.clump_shape.push_back({c.centre_m, c.radius_m});
  }
  return true;
}

// Records are keyed by parameter values, group and replicate; they depend on the experiment
// files as read, the fidelities, the seed, the clump count and what each parameter sets (not
// bounds or budgets).
std::string Fingerprint(const StudyFile& study, const StudyRuns& runs, uint64_t seed, int clumps) {
  std::ostringstream text;
  for (size_t k = 0; k < study.experiments.size(); ++k)
    text << study.experiments[k].file.document.dump() << "|"
         << FidelityJson(runs.fidelities[k]).dump() << "|";
  text << "seed=" << seed << "|clumps=" << clumps;
  for (size_t k = 0; k < study.space.parameters.size(); ++k) {
    const calibrate::Parameter& p = study.space.parameters[k];
    text << "|" << calibrate::PairPropertyKey(p.property) << ":" << study.parameter_materials[k].first
         << ":" << study.parameter_materials[k].second << ":" << calibrate::DescribeCondition(p.when)
         << ":" << p.curve;
  }
  for (const calibrate::ParameterCurve& c : study.space.curves)
    text << "|curve:" << c.covariate << ":" << calibrate::CurveFormKey(c.form);
  return core::Fnv1a64Hex(text.str());
}

int GroupIndex(const StudyFile& study, int experiment, const calibrate::Condition& condition,
               StudyRuns* out, const std::vector<core::Scene>& models, std::string* error) {
  const std::string key = std::filesystem::path(study.experiments[experiment].path).filename().string() +
                          "|" + calibrate::DescribeCondition(condition);
  for (size_t g = 0; g < out->groups.size(); ++g)
    if (out->groups[g].key == key) return static_cast<int>(g);
  calibrate::RunGroup group{key, out->probes[experiment].get(), models[experiment], {}, condition, {}};
  if (!ResolveSpaceFor(study, group.model, &group.space, error)) return -1;
  const objectives::Fidelity fidelity = out->fidelities[experiment];
  group.prepare = [fidelity](core::Scene* m) { objectives::ApplyFidelity(fidelity, m); };
  out->groups.push_back(std::move(group));
  return static_cast<int>(out->groups.size()) - 1;
}

bool Bind(int group, const std::string& observable, StudyRuns* out, std::string* error) {
  if (group < 0) return false;
  const std::vector<std::string> offered = out->groups[group].probe->Observables();
  if (std::find(offered.begin(), offered.end(), observable) == offered.end()) {
    *error = "a " + out->groups[group].probe->Kind() + " experiment does not measure " + observable;
    return false;
  }
  out->bindings.push_back({group, observable});
  return true;
}

// A candidate target without a condition reads the runs of the first target of its experiment
// (free: no runs of its own); with one, the runs of that condition.
calibrate::Condition CandidateCondition(const StudyFile& study, const StudyCandidateTarget& t) {
  if (!t.condition.empty()) return t.condition;
  for (const StudyTarget& target : study.targets)
    if (target.experiment == t.experiment) return target.condition;
  return t.condition;
}

}  // namespace

bool BuildStudyRuns(const StudyFile& study, bool quick, int clump_count, StudyRuns* out,
                    std::string* error) {
  std::vector<core::Scene> models;
  for (const StudyExperiment& e : study.experiments) {
    core::Scene model = e.file.model;
    if (clump_count > 0 && !SetClumpCount(study.clump_count, clump_count, &model, error)) return false;
    const objectives::Fidelity fidelity = quick ? e.file.quick_fidelity : e.file.fidelity;
    if (!fidelity.IsValid(error)) return *error = e.path + ": " + *error, false;
    core::Scene at_fidelity = model;
    objectives::ApplyFidelity(fidelity, &at_fidelity);
    out->probes.push_back(FindExperimentKind(e.file.experiment)->make_probe(e.file, at_fidelity, error));
    if (!out->probes.back()) return false;
    out->fidelities.push_back(fidelity);
    models.push_back(std::move(model));
  }
  for (const StudyTarget& t : study.targets)
    if (!Bind(GroupIndex(study, t.experiment, t.condition, out, models, error), t.target.observable, out, error))
      return *error = study.source + ": target '" + t.target.name + "': " + *error, false;
  for (const StudyCandidateTarget& t : study.candidate_targets)
    if (!Bind(GroupIndex(study, t.experiment, CandidateCondition(study, t), out, models, error),
              t.observable, out, error))
      return *error = study.source + ": candidate target '" + t.name + "': " + *error, false;
  const uint64_t seed = study.has_seed ? study.seed : study.experiment().seed;
  out->fingerprint = Fingerprint(study, *out, seed, clump_count);
  return true;
}

}  // namespace demcal::workflow
