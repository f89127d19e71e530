#pragma once
// Calibrate: tune the parameters of a ParameterSpace so that the simulated observables match a
// list of measured targets, with an optimiser from the registry (optimiser.h). Candidates are
// asked for in batches from a CandidateEvaluator (which runs, journals and resumes the
// simulations); every candidate is reported through a progress callback and kept in the
// summary. At the best candidate the summary gives:
//  - per-target residuals, standardised by the measurement uncertainty;
//  - the sensitivity matrix J (response_surface.h, fitted to the evaluated candidates near the
//    best; each row divided by sqrt(1 + noise²), so measurement and simulation noise both count);
//  - parameters with σ (SI) and correlations: ceres::Covariance when the "ceres" optimiser
//    computed it, else the SVD pseudo-inverse of JᵀJ (parameter_covariance.h); a rank-deficient J
//    gives σ = +∞ and "not identifiable", never a fake finite σ;
//  - the identifiability report (identifiability.h): singular values, condition number and the
//    parameter combinations the targets leave undetermined, in words.
//
//   CalibrationSummary s = Calibrate(evaluator, space, targets, options, progress);
//   std::cerr << s.BriefReport(space);
//
// Thread-safety: Calibrate runs on the calling thread; the evaluator parallelises.
#include <Eigen/Dense>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "calibrate/candidate_evaluator.h"
#include "calibrate/identifiability.h"
#include "calibrate/local_crossing.h"
#include "calibrate/optimiser.h"
#include "calibrate/parameter_space.h"
#include "calibrate/response_surface.h"
#include "calibrate/target.h"

namespace demcal::calibrate {

struct CalibrationOptions {
  std::string optimiser = "bracket";
  OptimiserOptions optimiser_options;
  ResponseSurfaceOptions response_surface;
  // A candidate within noise but less precise than a measurement (TrialResult::Inconclusive) is
  // re-run with the replicates that bring its sem to the measurement uncertainty (sem ∝ 1/√n),
  // at most this multiple of the replicates it had (1: never). Such a candidate is no match
  // until then: it would be "within noise" of almost anything.
  int max_replicate_factor = 4;
  // Rounds of sensitivity refinement (sensitivity_refinement.h) when a parameter ends with
  // σ = +∞ although the targets are at least as many as the parameters; in [0, 10].
  int sensitivity_rounds = 2;
};

// One candidate the optimiser asked for.
struct Candidate {
  int index = 0;                   // 0, 1, ... in the order asked
  std::vector<double> parameters;  // SI
  std::vector<double> unit;        // unit cube
  CandidateResult result;
  TrialResult trial;  // standardised residuals (ok = false: infeasible)
  int replicates_added = 0;  // per group, beyond the evaluator's count (CalibrationOptions)
};

struct TargetResidual {
  std::string name, observable;
  double measured = 0, uncertainty = 0, simulated = 0, sem = 0;
  double residual = 0;        // (simulated − measured) / uncertainty
  bool within_noise = false;  // |residual| ≤ sqrt(1 + (sem/uncertainty)²)
};

struct ParameterEstimate {
  std::string name;
  double value = 0;           // SI, at the best candidate
  double sigma = 0;           // SI; +∞ when not determined (rank-deficient J or no J)
  bool identifiable = false;  // finite σ within the bounds' own spread (parameter_covariance.h)
};

// Called after every candidate (the journal already holds its replicates).
using CandidateProgress = std::function<void(const Candidate& candidate, double elapsed_s)>;

struct CalibrationSummary {
  Termination termination = Termination::kFailed;  // the optimiser's, or kInvalid
  std::string message = "Calibrate was not called";
  std::vector<Candidate> candidates;  // in the order evaluated
  int best = -1;                      // index into candidates, −1 if none gave a value
  int batches = 0;
  std::vector<TargetResidual> residuals;     // per target at the best
  std::vector<ParameterEstimate> estimates;  // per parameter
  Eigen::MatrixXd correlation;               // n×n, NaN where undefined (σ = +∞)
  Eigen::MatrixXd covariance;                // SI, n×n, NaN where undefined
  std::string covariance_note;               // how σ was obtained, or why it is not given
  Eigen::MatrixXd jacobian;                  // targets × parameters, standardised, per unit cube
  Eigen::MatrixXd jacobian_sigma;            // its standard errors
  std::string jacobian_note;
  IdentifiabilityReport identifiability;
  int replicates_run = 0;
  int replicates_reused = 0;  // found in the journal (resumed work)
  int refinement_points = 0;  // candidates added after the optimiser to sharpen J (also in candidates)
  std::string journal_error;  // first failure to write the journal ("" if none)
  // One parameter and one target, no candidate within noise: the crossing of a line through the
  // candidates around the measurement (local_crossing.h), and its value and σ in SI (NaN: not
  // fitted). Offered beside the best candidate; termination and best are the optimiser's.
  LocalCrossing local_crossing;
  double local_crossing_value = std::numeric_limits<double>::quiet_NaN();
  double local_crossing_sigma = std::numeric_limits<double>::quiet_NaN();

  bool ok() const { return best >= 0 && termination == Termination::kWithinNoise; }
  std::string BriefReport(const ParameterSpace& space) const;
};

CalibrationSummary Calibrate(CandidateEvaluator& evaluator, const ParameterSpace& space,
                             const std::vector<Target>& targets, const CalibrationOptions& options,
                             const CandidateProgress& progress = {});

}  // namespace demcal::calibrate
