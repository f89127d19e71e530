#include "diagnose/run_diagnose.h"

#include <algorithm>
#include <sstream>

#include "diagnose/dem/effect_context.h"
#include "diagnose/dem/study_model.h"
#include "diagnose/effects/effect_registry.h"
#include "diagnose/report/diagnosis_outputs.h"
#include "files/measurement_table.h"
#include "objectives/farm/farm.h"
#include "outputs/exit_codes.h"
#include "outputs/output_lock.h"
#include "workflow/calibration/study_file.h"

namespace demcal::diagnose {
namespace {

bool ChooseEffects(const std::vector<std::string>& keys, std::vector<const Effect*>* out,
                   std::string* error) {
  if (keys.empty()) return *out = EffectLibrary(), true;
  for (const std::string& k : keys) {
    const Effect* e = FindEffect(k);
    if (!e)
      return *error = "--effects: unknown effect '" + k + "'; the library: " + EffectKeys(), false;
    out->push_back(e);
  }
  return true;
}

// The index of the study's parameter that fits the property of the pair (subject material, one
// of `others`); −1 when none does.
int Fits(const workflow::StudyFile& study, calibrate::PairProperty property,
         const std::string& material, const std::vector<std::string>& others) {
  const core::Scene& model = study.experiment().model;
  const int m = model.MaterialIndex(material);
  const std::vector<calibrate::Parameter>& parameters = study.space.parameters;
  for (size_t j = 0; j < parameters.size(); ++j) {
    const calibrate::Parameter& p = parameters[j];
    if (p.property != property || p.curve >= 0) continue;
    for (const std::string& other : others) {
      const int o = model.MaterialIndex(other);
      if ((p.material_i == m && p.material_j == o) || (p.material_i == o && p.material_j == m))
        return static_cast<int>(j);
    }
  }
  return -1;
}

// A candidate that shifts a property the study already fits is a copy of a fitted parameter:
// guarded like the control, never named (docs/diagnose/ranking.md). The index of the parameter
// it copies (−1: none; the sliding-friction control is a control even when the study does not
// fit μs).
int CopiedParameter(const std::string& key, const workflow::StudyFile& study,
                    const EffectContext& c) {
  using calibrate::PairProperty;
  if (key == "sliding_friction_control")
    return Fits(study, PairProperty::kSlidingFriction, c.material, {c.material});
  if (key == "rolling_resistance")
    return Fits(study, PairProperty::kRollingFriction, c.material, {c.material});
  if (key == "jkr_adhesion")
    return Fits(study, PairProperty::kInterfacialEnergy, c.material, {c.material});
  if (key == "sjkr_cohesion")
    return Fits(study, PairProperty::kCohesionEnergyDensity, c.material, {c.material});
  if (key == "wall_friction")
    return Fits(study, PairProperty::kSlidingFriction, c.material, c.wall_materials);
  return -1;
}

DiagnosisRunInfo RunInfo(const DiagnoseCommandOptions& o, const workflow::StudyFile& study,
                         const EffectContext& c, const std::vector<CandidateEffect>& candidates,
                         const Diagnosis& d, const StudyModel& m) {
  DiagnosisRunInfo info{o.study_path, study.description};
  const workflow::ExperimentFile& e = study.experiment();
  for (const workflow::StudyTarget& t : study.targets) {
    info.synthetic = info.synthetic || workflow::IsModelMadeProvenance(t.provenance);
    if (std::find(info.data_provenance.begin(), info.data_provenance.end(), t.provenance) ==
        info.data_provenance.end())
      info.data_provenance.push_back(t.provenance);
  }
  info.fidelity = (o.quick ? e.quick_fidelity : e.fidelity).name;
  info.seed = study.has_seed ? study.seed : e.seed;
  info.replicates = study.replicates > 0 ? study.replicates : e.replicates;
  info.options = o.diagnose;
  info.context = c;
  info.candidates = candidates;
  for (const calibrate::Parameter& p : study.space.parameters) info.base_names.push_back(p.name);
  if (!d.base.base_unit.empty()) info.base_before_si = study.space.FromUnit(d.base.base_unit);
  if (!d.final_point.base_unit.empty())
    info.base_after_si = study.space.FromUnit(d.final_point.base_unit);
  if (!d.bound_effect_base_unit.empty())
    info.bound_effect_base_si = study.space.FromUnit(d.bound_effect_base_unit);
  info.journal_error = m.journal_error();
  return info;
}

}  // namespace

int RunDiagnose(const DiagnoseCommandOptions& o, std::ostream& log) {
  using namespace demcal::workflow;
  std::string error;
  StudyFile study;
  if (!LoadStudyFile(o.study_path, &study, &error))
    return log << "error: " << error << "\n", kExitInvalidInput;
  study.candidate_targets.clear();  // a diagnosis fits the measured targets only
  if (study.clump_count.enabled())
    return log << "error: " << o.study_path
               << ": 'clump_count': not supported by diagnose (the shape is a "
               << "candidate effect here)\n",
           kExitInvalidInput;
  if (!o.diagnose.IsValid(&error)) return log << "error: " << error << "\n", kExitInvalidInput;
  std::vector<const Effect*> effects;
  EffectContext context;
  if (!ChooseEffects(o.effects, &effects, &error) ||
      !MakeEffectContext(study, o.species, &context, &error))
    return log << "error: " << error << "\n", kExitInvalidInput;
  OutputLock lock;
  // Under mpirun rank 0 locks and writes; the other ranks run simulations (farm.h).
  const bool writer = objectives::farm::IsManager();
  if (writer && !LockOutputDirectory(o.out_dir, "demcal diagnose " + o.study_path, &lock, &error))
    return log << "error: --out: " << error << "\n", kExitInvalidInput;
  std::vector<CandidateEffect> candidates;
  for (const Effect* e : effects) {
    const int copies = CopiedParameter(e->Key(), study, context);
    candidates.push_back({e->Key(), e->Description(), e->Parameters(context),
                          copies >= 0 || e->Key() == "sliding_friction_control", copies,
                          e->Mechanism()});
  }
  StudyModelOptions mo{o.out_dir, o.quick, o.threads, o.max_evaluations, o.quiet ? nullptr : &log};
  std::unique_ptr<StudyModel> model = StudyModel::Create(study, effects, context, mo, &error);
  if (!model) return log << "error: " << error << "\n", kExitInvalidInput;
  const DiagnoseProgress progress = [&log, &o](const std::string& line) {
    if (!o.quiet) log << "diagnose: " << line << "\n" << std::flush;
  };
  if (!o.quiet)
    log << "diagnose: " << study.targets.size() << " observations; subject species "
        << context.species
        << (context.coating_column.empty() ? "" : "; coating column " + context.coating_column)
        << "; " << candidates.size() << " candidate effects\n";
  const Diagnosis d = Diagnose(*model, model->Observations(), candidates, o.diagnose, progress);
  if (!model->journal_error().empty())
    return log << "error: " << model->journal_error() << "; the diagnosis stopped there: make room "
               << "and run the same command again to resume\n", kExitOutputError;
  if (d.termination == DiagnosisTermination::kInvalid)
    return log << "error: " << d.message << "\n", kExitInvalidInput;
  if (writer &&
      !WriteDiagnosisOutputs(o.out_dir, RunInfo(o, study, context, candidates, d, *model), d,
                             &error))
    return log << "error: " << error << "\n", kExitOutputError;
  std::ostringstream times;
  for (const PhaseTime& p : d.phases)
    times << " " << p.phase << " " << p.simulations << " runs " << p.wall_time_s << " s;";
  if (!o.quiet)
    log << "diagnose: " << d.message << "\ndiagnose: " << d.simulations << " simulations ("
        << d.simulations_reused << " from journal), " << d.wall_time_s << " s:" << times.str()
        << "\ndiagnose: outputs in " << o.out_dir << " (diagnosis.json)\n";
  return d.termination == DiagnosisTermination::kFailed ? kExitRunFailed : kExitOk;
}

}  // namespace demcal::diagnose
