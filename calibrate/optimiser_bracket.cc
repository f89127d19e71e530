// "bracket": one parameter against one measurement, for an observable that changes monotonically
// with it (a repose angle against friction or Γ). Root finding is far cheaper than minimising
// a sum of squares here: evaluate the start and both bounds; if the measurement lies between
// two of them, close in on the crossing by regula falsi with the Illinois modification (the
// retained end's residual is halved when it is kept twice, so the bracket shrinks from both
// sides), stopping at the first candidate within noise, when the bracket is narrower than
// unit_tolerance, or at the budget. Without a sign change the measurement is out of the bounds'
// reach: the result says so (with the nearest candidate) instead of pretending a fit. A bound
// that gives no value (heaps that never settle at an extreme friction, say) is replaced by the
// point half-way towards the start, up to kRetreats times; the message names what happened.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibrate/optimiser.h"

namespace demcal::calibrate {
namespace {

constexpr int kRetreats = 3;

struct Point {
  double u = 0;
  TrialResult trial;
  bool settled = false;  // the search may stop here (MatchRecord; one target: within noise)
  double r() const { return trial.residuals[0]; }
};

class Search {
 public:
  Search(const BatchTrialFunction& f, const OptimiserOptions& o) : f_(f), options_(o) {}

  bool Budget() const { return result_.evaluations >= options_.max_evaluations; }
  // Evaluates u; false if the trial failed (result_ says why).
  bool Eval(double u, Point* p) {
    p->u = u;
    p->trial = EvaluateOne(f_, {u});
    ++result_.batches;
    ++result_.evaluations;
    if (!p->trial.ok || p->trial.residuals.size() != 1) return false;
    p->settled = record_.Note(p->trial);
    if (result_.best_unit.empty() || p->trial.Cost() < result_.best_cost) {
      result_.best_unit = {u};
      result_.best_cost = p->trial.Cost();
    }
    return true;
  }
  OptimiserResult Finish(Termination termination, const std::string& message) {
    result_.termination = termination;
    result_.message = retreated_ && termination != Termination::kOutOfRange
                          ? message + " (a bound gave no value: probed nearer the start)"
                          : message;
    return result_;
  }
  OptimiserResult Run(double start);

 private:
  // Evaluates the bound, or failing that points half-way back towards `from`; false if none
  // gave a value.
  bool Probe(double from, double bound, Point* p) {
    for (int k = 0; k <= kRetreats && !Budget(); ++k, bound = 0.5 * (from + bound)) {
      if (Eval(bound, p)) return true;
      retreated_ = true;
    }
    return false;
  }
  bool retreated_ = false;
  MatchRecord record_{1};
  OptimiserResult Refine(Point a, Point b);
  const BatchTrialFunction& f_;
  const OptimiserOptions& options_;
  OptimiserResult result_;
};

OptimiserResult Search::Run(double start) {
  Point s, lo, hi;
  if (!Eval(start, &s)) return Finish(Termination::kFailed, "the start candidate gave no value");
  if (s.settled) return Finish(Termination::kWithinNoise, "the start candidate matches within noise");
  if (Budget()) return Finish(Termination::kBudget, "budget used up at the start candidate");
  // Probe the bound on the side the residual says the root lies (assuming an increasing
  // observable); the other bound only if that shows no sign change.
  const bool up_first = s.r() < 0;
  Point& first = up_first ? hi : lo;
  Point& second = up_first ? lo : hi;
  if (!Probe(start, up_first ? 1.0 : 0.0, &first))
    return Finish(Termination::kFailed, "a bound and the points towards the start gave no value");
  if (first.settled) return Finish(Termination::kWithinNoise, "a bound matches within noise");
  if (first.r() * s.r() < 0) return up_first ? Refine(s, first) : Refine(first, s);
  if (Budget()) return Finish(Termination::kBudget, "budget used up probing the bounds");
  if (!Probe(start, up_first ? 0.0 : 1.0, &second))
    return Finish(Termination::kFailed, "a bound and the points towards the start gave no value");
  if (second.settled) return Finish(Termination::kWithinNoise, "a bound matches within noise");
  if (second.r() * s.r() < 0) return up_first ? Refine(second, s) : Refine(s, second);
  std::ostringstream m;
  if (retreated_) m << "(a bound gave no value; the nearest point that did is used) ";
  m << "the measurement is outside the range the bounds reach (standardised residuals "
    << lo.r() << " at the lower bound, " << s.r() << " at the start, " << hi.r()
    << " at the upper bound): widen the bounds or add the missing effect";
  return Finish(Termination::kOutOfRange, m.str());
}

OptimiserResult Search::Refine(Point a, Point b) {
  double fa = a.r(), fb = b.r();
  int kept = 0;  // +1: a kept repeatedly, −1: b kept repeatedly
  while (b.u - a.u > options_.unit_tolerance) {
    if (Budget()) return Finish(Termination::kBudget, "budget used up before a match within noise");
    const double u = std::clamp(b.u - fb * (b.u - a.u) / (fb - fa), a.u + 0.01 * (b.u - a.u),
                                b.u - 0.01 * (b.u - a.u));
    Point p;
    if (!Eval(u, &p)) return Finish(Termination::kFailed, "a candidate inside the bracket gave no value");
    if (p.settled) return Finish(Termination::kWithinNoise, "matched within noise");
    if (p.r() * fa < 0) {  // the crossing is in [a, p]
      b = p, fb = p.r();
      if (kept == 1) fa *= 0.5;
      kept = 1;
    } else {
      a = p, fa = p.r();
      if (kept == -1) fb *= 0.5;
      kept = -1;
    }
  }
  return Finish(Termination::kConverged, "bracket narrower than unit_tolerance without a match within noise "
                             "(the observable may jump here, or its noise is underestimated)");
}

}  // namespace

OptimiserResult BracketOptimise(const BatchTrialFunction& trial, const std::vector<double>& start_unit,
                                const OptimiserOptions& options) {
  Search search(trial, options);
  if (start_unit.size() != 1)
    return search.Finish(Termination::kFailed, "bracket optimises exactly one parameter (use an nlopt_* optimiser)");
  return search.Run(start_unit[0]);
}

}  // namespace demcal::calibrate
