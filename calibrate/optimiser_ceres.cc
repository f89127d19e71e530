// "ceres": least squares on the standardised residual vector with ceres::Problem and a
// Levenberg–Marquardt trust region in the unit cube (bounds by SetParameterLowerBound /
// SetParameterUpperBound), then ceres::Covariance at the best candidate.
//
// Residuals. Each residual r_k = (simulated − measured) / u_k is divided by sqrt(1 + noise_k²)
// at the start candidate, so the sum of squares is a chi-square against the measurement *and*
// the simulation noise. The weights are fixed for the run (taken once, at the start) so that the
// objective is one smooth function and the run is deterministic.
//
// Derivatives. DEM observables are noisy, so the Jacobian comes from finite differences with a
// step larger than the noise, chosen from the noise and the bounds:
//   h = clamp(kSignalToNoise · noise_max / kMinSensitivity, kMinStep, kMaxStep)   (unit cube;
//   FiniteDifferenceStep in sensitivity_refinement.cc, which refines J with the same rule)
// kMinSensitivity = sqrt(12) is the smallest |d r / d u| that tells a parameter anything beyond its
// bounds (identifiability.h: a uniform prior on [0, 1] has σ = 1/sqrt(12)); with this h such a
// sensitivity moves the residual by kSignalToNoise = 4 times the noise over the step, so the
// noise error of the derivative (≈ noise / (sqrt 2 · h) for a central difference) stays below a
// quarter of it. kMinStep = 0.01 keeps a step when the simulation is noise-free; kMaxStep = 0.25
// keeps the linearisation local. Central differences where both sides lie in the cube and give a
// value, one-sided from the centre at a bound or next to a failed sample. The centre and all
// 2n (or n) offsets are requested as one batch.
//
// Stops: at the first candidate that has settled within noise (TrialResult::Settled: inside the
// parameters' 1σ region, no refining beyond noise), at Ceres' own tolerances (converged), or when
// the next batch would exceed max_evaluations (budget). The termination is within_noise whenever
// some candidate matched (TrialResult::WithinNoise), settled or not. A failed sample (ok = false)
// makes CostFunction::Evaluate return false: Ceres treats it as infeasible and shrinks its step.
// Candidates already evaluated are not asked again.
//
// Candidate lattice. Every point Ceres asks for is rounded to the lattice of spacing
// unit_tolerance in the unit cube, so points closer than the tolerance are one candidate (run
// once, then read back). Without it, a rejected step on a noisy objective made Ceres shrink its
// trust region and ask for points 1e-3, 1e-5, 1e-8 away from the same centre, each with a full
// finite-difference stencil of new runs (seen on the DEM twin: 12 of its 29 candidates lay
// within 2e-3 of earlier ones). On the lattice such a step lands on a known point, the cost does not change,
// and Ceres stops at its parameter tolerance instead.
#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "calibrate/jacobian_svd.h"
#include "calibrate/optimiser.h"
#include "calibrate/sensitivity_refinement.h"

namespace demcal::calibrate {
namespace {

// The candidates asked so far, the budget and the best; shared by the cost function and the
// callback of one run.
class Trials {
 public:
  Trials(const BatchTrialFunction& f, const OptimiserOptions& o, OptimiserResult* r, size_t parameters)
      : f_(f), options_(o), result_(r), record_(parameters) {}

  // Evaluates the points not yet known (one batch); false (and stop()) if that would exceed the
  // budget.
  bool Ensure(const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> todo;
    for (const auto& p : points)
      if (!known_.count(p) && std::find(todo.begin(), todo.end(), p) == todo.end())
        todo.push_back(p);
    if (todo.empty()) return true;
    if (result_->evaluations + static_cast<int>(todo.size()) > options_.max_evaluations) {
      budget_hit_ = halt_ = true;
      return false;
    }
    std::vector<TrialResult> out = f_(todo);
    ++result_->batches;
    for (size_t i = 0; i < todo.size(); ++i) {
      TrialResult t = i < out.size() ? out[i] : TrialResult{};
      for (double r : t.residuals)
        if (!std::isfinite(r)) t.ok = false;
      if (t.ok && residuals_ && t.residuals.size() != residuals_) t.ok = false;
      ++result_->evaluations;
      if (t.ok && (result_->best_unit.empty() || t.Cost() < result_->best_cost))
        result_->best_unit = todo[i], result_->best_cost = t.Cost();
      if (record_.Note(t)) halt_ = true;
      known_[todo[i]] = std::move(t);
    }
    return true;
  }
  const TrialResult& At(const std::vector<double>& p) const { return known_.at(p); }
  void SetResidualCount(size_t m) { residuals_ = m; }
  bool stop() const { return halt_; }
  void Release() { halt_ = false; }
  bool matched() const { return record_.matched(); }
  bool settled() const { return record_.settled(); }
  bool budget_hit() const { return budget_hit_; }

 private:
  const BatchTrialFunction& f_;
  const OptimiserOptions& options_;
  OptimiserResult* result_;
  std::map<std::vector<double>, TrialResult> known_;
  MatchRecord record_;
  size_t residuals_ = 0;
  bool budget_hit_ = false, halt_ = false;
};

// x rounded to the lattice of spacing `tolerance` in [0, 1] (see above).
std::vector<double> Snap(std::vector<double> x, double tolerance) {
  for (double& v : x) v = std::clamp(std::round(v / tolerance) * tolerance, 0.0, 1.0);
  return x;
}

class FiniteDifferenceCost final : public ceres::CostFunction {
 public:
  FiniteDifferenceCost(Trials* trials, std::vector<double> weights, double step, int n,
                       double lattice)
      : trials_(trials), weights_(std::move(weights)), step_(step), n_(n), lattice_(lattice) {
    set_num_residuals(static_cast<int>(weights_.size()));
    mutable_parameter_block_sizes()->push_back(n);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    if (trials_->stop()) return false;  // the callback ends the solve
    const std::vector<double> x =
        Snap(std::vector<double>(parameters[0], parameters[0] + n_), lattice_);
    std::vector<std::vector<double>> points{x};
    std::vector<int> lo(n_, 0), hi(n_, 0);  // indices of the offset points (0: the centre)
    const bool jacobian = jacobians && jacobians[0];
    if (jacobian)
      for (int k = 0; k < n_; ++k) {
        if (x[k] + step_ <= 1) hi[k] = Push(x, k, step_, lattice_, &points);
        if (x[k] - step_ >= 0) lo[k] = Push(x, k, -step_, lattice_, &points);
      }
    if (!trials_->Ensure(points)) return false;
    const TrialResult& c = trials_->At(x);
    if (!c.ok) return false;
    const int m = num_residuals();
    for (int i = 0; i < m; ++i) residuals[i] = weights_[i] * c.residuals[i];
    if (!jacobian) return true;
    for (int k = 0; k < n_; ++k) {
      // Central where both offsets gave a value, else one-sided from the centre.
      if (!trials_->At(points[hi[k]]).ok) hi[k] = 0;
      if (!trials_->At(points[lo[k]]).ok) lo[k] = 0;
      if (hi[k] == lo[k]) return false;  // neither side gave a value: infeasible here
      const TrialResult& a = trials_->At(points[lo[k]]);
      const TrialResult& b = trials_->At(points[hi[k]]);
      const double du = points[hi[k]][k] - points[lo[k]][k];
      for (int i = 0; i < m; ++i)
        jacobians[0][i * n_ + k] = weights_[i] * (b.residuals[i] - a.residuals[i]) / du;
    }
    return true;
  }

 private:
  static int Push(const std::vector<double>& x, int k, double h, double lattice,
                  std::vector<std::vector<double>>* points) {
    std::vector<double> offset = x;
    offset[k] += h;
    points->push_back(Snap(offset, lattice));
    return static_cast<int>(points->size()) - 1;
  }
  Trials* trials_;
  std::vector<double> weights_;
  double step_;
  int n_;
  double lattice_;
};

class StopWhenTold final : public ceres::IterationCallback {
 public:
  explicit StopWhenTold(const Trials* trials) : trials_(trials) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return trials_->stop() ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  const Trials* trials_;
};

// ceres::Covariance of the unit parameters at `best` (DENSE_SVD; false on a rank-deficient J).
void Covariance(ceres::Problem* problem, const ceres::CostFunction& cost, Trials* trials, double* x,
                const std::vector<double>& best, OptimiserResult* result) {
  const int n = static_cast<int>(best.size());
  std::copy(best.begin(), best.end(), x);
  // ceres::Covariance does not survive a failing Evaluate: try the Jacobian here first.
  std::vector<double> r(cost.num_residuals()), j(cost.num_residuals() * n);
  double* jacobians[] = {j.data()};
  const double* parameters[] = {x};
  const bool evaluated = cost.Evaluate(parameters, r.data(), jacobians);
  // A point of that stencil may have matched within noise, which asks the solve to stop; the
  // solve is over, and ceres::Covariance must see the same Evaluate succeed.
  trials->Release();
  if (!evaluated) {
    result->covariance_note =
        "ceres::Covariance: not computed (the finite-difference points of the best candidate "
        "are beyond the budget or gave no value)";
    return;
  }
  // ceres::Covariance's DENSE_SVD sees only min(m, n) singular values, so fewer residuals than
  // parameters would pass as full rank: judge the rank on the Jacobian itself.
  const Eigen::MatrixXd jacobian =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          j.data(), cost.num_residuals(), n);
  if (DecomposeJacobian(jacobian).rank < n) {
    result->covariance_note =
        "ceres::Covariance: not computed (rank-deficient Jacobian: some parameter combination is "
        "not determined)";
    return;
  }
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.null_space_rank = 0;  // a rank-deficient Jacobian fails rather than give fake σ
  ceres::Covariance covariance(options);
  const std::vector<std::pair<const double*, const double*>> blocks{{x, x}};
  if (!covariance.Compute(blocks, problem)) {
    result->covariance_note =
        "ceres::Covariance: not computed (rank-deficient Jacobian: some parameter combination is "
        "not determined)";
    return;
  }
  result->covariance_unit.assign(n * n, 0.0);
  covariance.GetCovarianceBlock(x, x, result->covariance_unit.data());
  result->covariance_note = "ceres::Covariance (DENSE_SVD) at the best candidate";
}

}  // namespace

OptimiserResult CeresOptimise(const BatchTrialFunction& trial,
                              const std::vector<double>& start_unit,
                              const OptimiserOptions& options) {
  OptimiserResult result;
  const int n = static_cast<int>(start_unit.size());
  if (n < 1) return result.message = "no parameters", result;
  std::vector<double> x = Snap(start_unit, options.unit_tolerance);
  Trials trials(trial, options, &result, static_cast<size_t>(n));
  trials.Ensure({x});
  const TrialResult start = trials.At(x);
  if (!start.ok || start.residuals.empty()) {
    result.message = "the start candidate gave no value";
    return result;
  }
  if (trials.settled()) {  // the start went through the shared stop rule
    result.termination = Termination::kWithinNoise;
    result.message = "the start candidate matches within noise";
    return result;
  }
  trials.SetResidualCount(start.residuals.size());
  std::vector<double> weights;
  double noise_max = 0;
  for (size_t k = 0; k < start.residuals.size(); ++k) {
    const double noise = k < start.noise.size() ? start.noise[k] : 0.0;
    weights.push_back(1 / std::sqrt(1 + noise * noise));
    noise_max = std::max(noise_max, noise);
  }
  const double step = FiniteDifferenceStep(noise_max);

  ceres::Problem problem;
  auto* cost = new FiniteDifferenceCost(&trials, weights, step, n,
                                        options.unit_tolerance);  // owned by the problem
  problem.AddResidualBlock(cost, nullptr, x.data());
  for (int k = 0; k < n; ++k) {
    problem.SetParameterLowerBound(x.data(), k, 0.0);
    problem.SetParameterUpperBound(x.data(), k, 1.0);
  }
  StopWhenTold stop(&trials);
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.logging_type = ceres::SILENT;
  so.num_threads = 1;
  so.max_num_iterations = options.max_evaluations;
  so.parameter_tolerance = options.unit_tolerance;
  so.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);

  std::ostringstream m;
  m << "finite-difference step " << step << " (unit cube), " << summary.iterations.size()
    << " Ceres iterations";
  if (trials.settled()) {
    result.termination = Termination::kWithinNoise;
    result.message = "matched and settled within noise; " + m.str();
  } else if (trials.matched()) {
    result.termination = Termination::kWithinNoise;
    result.message = "matched within noise, then searched on to Ceres' " +
                     std::string(trials.budget_hit() ? "budget" : "tolerance") + "; " + m.str();
  } else if (trials.budget_hit()) {
    result.termination = Termination::kBudget;
    result.message = "budget used up before a match within noise; " + m.str();
  } else if (summary.termination_type == ceres::CONVERGENCE) {
    result.termination = Termination::kConverged;
    result.message = "Ceres converged without a match within noise (" + summary.message + "); " +
                     m.str() + ": the measurements may be out of the bounds' reach or conflict";
  } else if (summary.termination_type == ceres::NO_CONVERGENCE) {
    result.termination = Termination::kBudget;
    result.message = "Ceres iteration limit; " + m.str();
  } else {
    result.termination = Termination::kFailed;
    result.message = "Ceres: " + summary.message + "; " + m.str();
  }
  // The covariance's Jacobian at the best candidate: its finite-difference points are usually
  // known already; missing ones are evaluated only if the budget still allows.
  trials.Release();
  if (!result.best_unit.empty()) Covariance(&problem, *cost, &trials, x.data(), result.best_unit, &result);
  return result;
}

}  // namespace demcal::calibrate
