// StudyModel::CalibrateBase: the study's own calibration (Calibration II) with no effect
// switched on, through the "no effects" setting's evaluator and journal, and the base model's
// sensitivities from a response surface over the candidates it evaluated.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "calibrate/calibration.h"
#include "calibrate/parameter_covariance.h"
#include "calibrate/response_surface.h"
#include "diagnose/dem/study_model.h"

namespace demcal::diagnose {
namespace {

// d mean / d unit per target (observable units), from the evaluated candidates near the best,
// with the standard errors of those sensitivities.
bool Sensitivities(const calibrate::CalibrationSummary& s,
                   const std::vector<calibrate::Target>& targets,
                   std::vector<std::vector<double>>* jacobian,
                   std::vector<std::vector<double>>* jacobian_sigma, std::string* message) {
  std::vector<calibrate::Sample> samples;
  for (const calibrate::Candidate& c : s.candidates) {
    if (!c.result.ok()) continue;
    calibrate::TrialResult t{true};
    for (size_t k = 0; k < targets.size(); ++k) {
      t.residuals.push_back(c.result.targets[k].mean / targets[k].uncertainty);
      t.noise.push_back(c.result.targets[k].sem / targets[k].uncertainty);
    }
    samples.push_back({c.unit, t});
  }
  const calibrate::ResponseSurface surface =
      calibrate::FitResponseSurface(samples, s.candidates[s.best].unit);
  *message = surface.message;
  if (!surface.ok) return false;
  jacobian->assign(targets.size(), std::vector<double>(surface.jacobian.cols()));
  jacobian_sigma->assign(targets.size(), std::vector<double>(surface.jacobian.cols()));
  for (size_t k = 0; k < targets.size(); ++k)
    for (Eigen::Index j = 0; j < surface.jacobian.cols(); ++j) {
      (*jacobian)[k][j] = surface.jacobian(k, j) * targets[k].uncertainty;
      (*jacobian_sigma)[k][j] = surface.jacobian_sigma(k, j) * targets[k].uncertainty;
    }
  return true;
}

}  // namespace

std::vector<std::string> StudyModel::BaseParameterNames() const {
  std::vector<std::string> names;
  for (const calibrate::Parameter& p : study_.space.parameters) names.push_back(p.name);
  return names;
}

std::vector<double> StudyModel::BaseSiPerUnit(const std::vector<double>& unit) const {
  return calibrate::SiPerUnit(study_.space, unit);
}

BaseCalibration StudyModel::CalibrateBase(int budget_scale) {
  BaseCalibration base;
  std::string error;
  Setting* s = SettingFor({}, &error);
  if (!s) return base.message = error, base;
  calibrate::CalibrationOptions options = study_.options;
  if (options_.max_evaluations > 0)
    options.optimiser_options.max_evaluations = options_.max_evaluations;
  options.optimiser_options.max_evaluations *= std::max(1, budget_scale);
  base.max_evaluations = options.optimiser_options.max_evaluations;
  std::vector<calibrate::Target> targets;
  for (const workflow::StudyTarget& t : study_.targets) targets.push_back(t.target);
  calibrate::CandidateProgress progress;
  if (options_.log)
    progress = [this](const calibrate::Candidate& c, double elapsed) {
      *options_.log << "diagnose:   base candidate " << c.index + 1 << " "
                    << study_.space.Describe(c.parameters) << " -> cost "
                    << (c.trial.ok ? c.trial.Cost() : NAN) << " (" << std::lround(elapsed)
                    << " s)\n"
                    << std::flush;
    };
  const calibrate::CalibrationSummary summary =
      calibrate::Calibrate(*s->evaluator, study_.space, targets, options, progress);
  run_ += summary.replicates_run;
  reused_ += summary.replicates_reused;
  if (journal_error_.empty()) journal_error_ = summary.journal_error;
  Pool(s);
  base.termination = calibrate::TerminationName(summary.termination);
  base.settled = SettledTermination(base.termination);
  base.message = summary.message;
  if (summary.best < 0) return base;
  const calibrate::Candidate& best = summary.candidates[summary.best];
  base.base_unit = best.unit;
  base.prediction = Predict(*s, best.result);
  std::string why;
  if (!Sensitivities(summary, targets, &base.jacobian, &base.jacobian_sigma, &why)) {
    base.message += "; no sensitivities (" + why + "): the refits move only the effects";
    base.jacobian.assign(targets.size(), std::vector<double>(study_.space.Size(), 0.0));
    base.jacobian_sigma.clear();
  }
  base.ok = base.prediction.ok;
  return base;
}

}  // namespace demcal::diagnose
