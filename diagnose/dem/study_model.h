#pragma once
// StudyModel: the ForwardModel of a calibration study (docs/calibration.md) run with the DEM.
// The base calibration is the study's own (calibrate::Calibrate over a TargetEvaluator, its
// optimiser and budget, journal DIR/base/journal.jsonl); its sensitivities come from a response
// surface over the candidates it evaluated (no extra run). A point with effects switched on
// runs the study's run groups with the effects written into each group's full-scale model after
// the study's parameters and before the fidelity (effect.h); every distinct effect setting has
// its own journal DIR/journal/<hash>.jsonl, so a killed diagnosis resumes without repeating a
// run. Replicate r has the same seed everywhere (common random numbers), so groups whose
// condition does not enter a setting's model run once for all of them (shared_run_groups.h).
//
// The simulation scatter is pooled over every evaluation of the diagnosis, per observation, and
// so is the correlation of two observables read from one run (replicate_pool.h): the
// prediction's correlation matrix of its rows' simulation errors.
//
// Thread-safety: one call at a time (each batch runs side by side inside).
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "calibrate/evaluation_journal.h"
#include "calibrate/target_evaluator.h"
#include "diagnose/dem/replicate_pool.h"
#include "diagnose/effects/effect.h"
#include "diagnose/gap/observation.h"
#include "diagnose/loop/forward_model.h"
#include "workflow/calibration/study_file.h"
#include "workflow/calibration/study_runs.h"

namespace demcal::diagnose {

struct StudyModelOptions {
  std::string out_dir;
  bool quick = false;
  int threads = 0;              // runs side by side (0: all cores)
  int max_evaluations = 0;      // base calibration budget (0: the study's)
  std::ostream* log = nullptr;  // progress lines (nullptr: quiet)
};

class StudyModel final : public ForwardModel {
 public:
  // study: without candidate targets (the caller strips them); effects: one per candidate, in
  // the loop's order. Outlive the model.
  static std::unique_ptr<StudyModel> Create(const workflow::StudyFile& study,
                                            const std::vector<const Effect*>& effects,
                                            const EffectContext& context,
                                            const StudyModelOptions& options, std::string* error);
  int BaseParameters() const override { return static_cast<int>(study_.space.Size()); }
  BaseCalibration CalibrateBase(int budget_scale) override;
  std::vector<std::string> BaseParameterNames() const override;
  std::vector<double> BaseSiPerUnit(const std::vector<double>& unit) const override;
  std::vector<Prediction> Evaluate(const std::vector<ModelPoint>& points) override;
  int SimulationsRun() const override { return run_; }
  int SimulationsReused() const override { return reused_; }
  // The observations (targets, in the study's order) without simulated values.
  std::vector<Observation> Observations() const;
  const std::string& journal_error() const { return journal_error_; }
  // "rolling_resistance(delta_mu_r=0.2)"; "" for none.
  std::string DescribeEffects(const std::vector<ActiveEffect>& effects) const;

 private:
  struct Setting {
    std::unique_ptr<calibrate::EvaluationJournal> journal;
    std::unique_ptr<calibrate::TargetEvaluator> evaluator;
    std::vector<calibrate::TargetBinding> bindings;  // runs_.bindings on the merged groups
    int merged_groups = 0;  // run groups that are the same run as another (shared_run_groups.h)
    size_t pooled = 0;      // history entries already in the pool
    std::string invalid;  // why the effects cannot be applied ("" if they can)
  };
  StudyModel(const workflow::StudyFile& study, const std::vector<const Effect*>& effects,
             const EffectContext& context, const StudyModelOptions& options);
  Setting* SettingFor(const std::vector<ActiveEffect>& effects, std::string* error);
  void Pool(Setting* s);
  // The prediction of a setting's candidate; its sources number the (run group, observable)
  // pairs the targets are bound to, so targets of merged groups share one.
  Prediction Predict(const Setting& s, const calibrate::CandidateResult& result) const;

  const workflow::StudyFile& study_;
  std::vector<const Effect*> effects_;
  EffectContext context_;
  StudyModelOptions options_;
  workflow::StudyRuns runs_;
  int replicates_ = 2;
  uint64_t seed_ = 1;
  std::map<std::string, Setting> settings_;
  ReplicatePool pool_{0};  // per observation, and per pair read from one run
  int run_ = 0, reused_ = 0;
  std::string journal_error_;
};

}  // namespace demcal::diagnose
