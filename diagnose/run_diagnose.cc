#include "diagnose/run_diagnose.h"

#include <sstream>

#include "diagnose/dem/effect_context.h"
#include "diagnose/dem/study_model.h"
#include "diagnose/effects/effect_registry.h"
#include "diagnose/report/diagnosis_outputs.h"
#include "outputs/exit_codes.h"
#include "workflow/calibration/study_file.h"
#include "outputs/output_lock.h"

namespace demcal::diagnose {
namespace {

bool ChooseEffects(const std::vector<std::string>& keys, std::vector<const Effect*>* out, std::string* error) {
  if (keys.empty()) return *out = EffectLibrary(), true;
  for (const std::string& k : keys) {
    const Effect* e = FindEffect(k);
    if (!e) return *error = "--effects: unknown effect '" + k + "'; the library: " + EffectKeys(), false;
    out->push_back(e);
  }
  return true;
}

DiagnosisRunInfo RunInfo(const DiagnoseCommandOptions& o, const workflow::StudyFile& study, const EffectContext& c,
                         const std::vector<CandidateEffect>& candidates, const Diagnosis& d, const StudyModel& m) {
  DiagnosisRunInfo info{o.study_path, study.description};
  const workflow::ExperimentFile& e = study.experiment();
  for (const workflow::StudyTarget& t : study.targets) info.synthetic = info.synthetic || t.provenance == "synthetic";
  info.fidelity = (o.quick ? e.quick_fidelity : e.fidelity).name;
  info.seed = study.has_seed ? study.seed : e.seed;
  info.replicates = study.replicates > 0 ? study.replicates : e.replicates;
  info.options = o.diagnose;
  info.context = c;
  info.candidates = candidates;
  for (const calibrate::Parameter& p : study.space.parameters) info.base_names.push_back(p.name);
  if (!d.base.base_unit.empty()) info.base_before_si = study.space.FromUnit(d.base.base_unit);
  if (!d.final_point.base_unit.empty()) info.base_after_si = study.space.FromUnit(d.final_point.base_unit);
  info.journal_error = m.journal_error();
  return info;
}

}  // namespace

int RunDiagnose(const DiagnoseCommandOptions& o, std::ostream& log) {
  using namespace demcal::workflow;
  std::string error;
  StudyFile study;
  if (!LoadStudyFile(o.study_path, &study, &error)) return log << "error: " << error << "\n", kExitInvalidInput;
  study.candidate_targets.clear();  // a diagnosis fits the measured targets only
  if (study.clump_count.enabled())
    return log << "error: " << o.study_path << ": 'clump_count': not supported by diagnose (the shape is a "
               << "candidate effect here)\n", kExitInvalidInput;
  if (!o.diagnose.IsValid(&error)) return log << "error: " << error << "\n", kExitInvalidInput;
  std::vector<const Effect*> effects;
  EffectContext context;
  if (!ChooseEffects(o.effects, &effects, &error) || !MakeEffectContext(study, o.species, &context, &error))
    return log << "error: " << error << "\n", kExitInvalidInput;
  OutputLock lock;
  if (!LockOutputDirectory(o.out_dir, "demcal diagnose " + o.study_path, &lock, &error))
    return log << "error: --out: " << error << "\n", kExitInvalidInput;
  std::vector<CandidateEffect> candidates;
  for (const Effect* e : effects) candidates.push_back({e->Key(), e->Description(), e->Parameters(context)});
  StudyModelOptions mo{o.out_dir, o.quick, o.threads, o.max_evaluations, o.quiet ? nullptr : &log};
  std::unique_ptr<StudyModel> model = StudyModel::Create(study, effects, context, mo, &error);
  if (!model) return log << "error: " << error << "\n", kExitInvalidInput;
  const DiagnoseProgress progress = [&log, &o](const std::string& line) {
    if (!o.quiet) log << "diagnose: " << line << "\n" << std::flush;
  };
  if (!o.quiet)
    log << "diagnose: " << study.targets.size() << " observations; subject species " << context.species
        << (context.coating_column.empty() ? "" : "; coating column " + context.coating_column) << "; "
        << candidates.size() << " candidate effects\n";
  const Diagnosis d = Diagnose(*model, model->Observations(), candidates, o.diagnose, progress);
  if (!model->journal_error().empty())
    return log << "error: " << model->journal_error() << "; the diagnosis stopped there: make room "
               << "and run the same command again to resume\n", kExitOutputError;
  if (d.termination == DiagnosisTermination::kInvalid) return log << "error: " << d.message << "\n", kExitInvalidInput;
  if (!WriteDiagnosisOutputs(o.out_dir, RunInfo(o, study, context, candidates, d, *model), d, &error))
    return log << "error: " << error << "\n", kExitOutputError;
  std::ostringstream times;
  for (const PhaseTime& p : d.phases) times << " " << p.phase << " " << p.simulations << " runs " << p.wall_time_s << " s;";
  if (!o.quiet)
    log << "diagnose: " << d.message << "\ndiagnose: " << d.simulations << " simulations (" << d.simulations_reused
        << " from journal), " << d.wall_time_s << " s:" << times.str() << "\ndiagnose: outputs in " << o.out_dir
        << " (diagnosis.json)\n";
  return d.termination == DiagnosisTermination::kFailed ? kExitRunFailed : kExitOk;
}

}  // namespace demcal::diagnose
