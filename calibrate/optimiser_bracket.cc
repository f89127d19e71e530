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
//
// k-section (k = bracket_points > 1): a batch is evaluated side by side, so a round may hold k
// candidates for the wall time of one. The first batch is the start and both bounds (one round
// instead of two or three); each refining round is the regula-falsi point plus the k − 1 points
// that split the bracket into k equal parts, and the new bracket is the pair of neighbours
// between which the residual changes sign. The even points bound the shrink to 1/k a round
// whatever the secant does; the secant point keeps regula falsi's fast end game. A candidate of
// the round without a value is left out (the bracket stays wider); only a round without any
// value fails the search. For k = 1 the round is the regula-falsi point alone: the
// one-candidate search, unchanged (its failed candidate fails the search).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibrate/optimiser.h"

namespace demcal::calibrate {
namespace {

constexpr int kRetreats = 3;
// Candidates inside the bracket stay this fraction of its width from its ends and from each
// other: closer, their residuals differ by less than the noise and the round is wasted.
constexpr double kMargin = 0.01;

struct Point {
  double u = 0;
  TrialResult trial;
  bool settled = false;  // the search may stop here (MatchRecord; one target: within noise)
  bool ok() const { return trial.ok && trial.residuals.size() == 1; }
  double r() const { return trial.residuals[0]; }
};

class Search {
 public:
  Search(const BatchTrialFunction& f, const OptimiserOptions& o) : f_(f), options_(o) {}

  bool Budget() const { return result_.evaluations >= options_.max_evaluations; }
  int Left() const { return options_.max_evaluations - result_.evaluations; }
  // Evaluates u; false if the trial failed (result_ says why).
  bool Eval(double u, Point* p) {
    p->u = u;
    p->trial = EvaluateOne(f_, {u});
    ++result_.batches;
    ++result_.evaluations;
    return Note(p);
  }
  // Evaluates the points `us` as one batch, in order; false if any trial failed.
  bool EvalBatch(const std::vector<double>& us, std::vector<Point>* ps) {
    std::vector<std::vector<double>> units;
    for (double u : us) units.push_back({u});
    std::vector<TrialResult> out = f_(units);
    ++result_.batches;
    result_.evaluations += static_cast<int>(us.size());
    ps->assign(us.size(), Point{});
    bool all = true;
    for (size_t k = 0; k < us.size(); ++k) {
      Point& p = (*ps)[k];
      p.u = us[k];
      if (out.size() == us.size()) p.trial = std::move(out[k]);  // else: a failed sample
      for (double r : p.trial.residuals)
        if (!std::isfinite(r)) p.trial.ok = false;
      all = Note(&p) && all;
    }
    return all;
  }
  OptimiserResult Finish(Termination termination, const std::string& message) {
    result_.termination = termination;
    result_.message = retreated_ && termination != Termination::kOutOfRange
                          ? message + " (a bound gave no value: probed nearer the start)"
                          : message;
    if (failed_inside_) result_.message += " (some candidates inside the bracket gave no value)";
    return result_;
  }
  OptimiserResult Run(double start);

 private:
  bool Note(Point* p) {
    if (!p->ok()) return false;
    p->settled = record_.Note(p->trial);
    if (result_.best_unit.empty() || p->trial.Cost() < result_.best_cost) {
      result_.best_unit = {p->u};
      result_.best_cost = p->trial.Cost();
    }
    return true;
  }
  // Evaluates the bound, or failing that points half-way back towards `from`; false if none
  // gave a value. `tried`: *p already holds the bound's trial (the k-section's first batch).
  bool Probe(double from, double bound, Point* p, bool tried) {
    if (tried) {
      if (p->ok()) return true;
      retreated_ = true;
      bound = 0.5 * (from + bound);
    }
    for (int k = tried ? 1 : 0; k <= kRetreats && !Budget(); ++k, bound = 0.5 * (from + bound)) {
      if (Eval(bound, p)) return true;
      retreated_ = true;
    }
    return false;
  }
  // The candidates of one refining round in [a, b] (ascending), at most Left() of them.
  std::vector<double> Round(const Point& a, const Point& b, double fa, double fb) const;
  bool retreated_ = false;
  bool failed_inside_ = false;  // a k-section round had a candidate without a value
  MatchRecord record_{1};
  OptimiserResult Refine(Point a, Point b);
  const BatchTrialFunction& f_;
  const OptimiserOptions& options_;
  OptimiserResult result_;
};

OptimiserResult Search::Run(double start) {
  Point s, lo, hi;
  // k ≥ 2 (and a budget for it): the start and both bounds in one batch.
  const bool wide = options_.bracket_points > 1 && options_.max_evaluations >= 3;
  if (wide) {
    std::vector<Point> p;
    EvalBatch({start, 0.0, 1.0}, &p);
    s = p[0], lo = p[1], hi = p[2];
    if (!s.ok()) return Finish(Termination::kFailed, "the start candidate gave no value");
  } else if (!Eval(start, &s)) {
    return Finish(Termination::kFailed, "the start candidate gave no value");
  }
  if (s.settled) return Finish(Termination::kWithinNoise, "the start candidate matches within noise");
  if (wide && (lo.settled || hi.settled))
    return Finish(Termination::kWithinNoise, "a bound matches within noise");
  if (!wide && Budget())
    return Finish(Termination::kBudget, "budget used up at the start candidate");
  // Probe the bound on the side the residual says the root lies (assuming an increasing
  // observable); the other bound only if that shows no sign change.
  const bool up_first = s.r() < 0;
  Point& first = up_first ? hi : lo;
  Point& second = up_first ? lo : hi;
  if (!Probe(start, up_first ? 1.0 : 0.0, &first, wide))
    return Finish(Termination::kFailed, "a bound and the points towards the start gave no value");
  if (first.settled) return Finish(Termination::kWithinNoise, "a bound matches within noise");
  if (first.r() * s.r() < 0) return up_first ? Refine(s, first) : Refine(first, s);
  if (Budget()) return Finish(Termination::kBudget, "budget used up probing the bounds");
  if (!Probe(start, up_first ? 0.0 : 1.0, &second, wide))
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

std::vector<double> Search::Round(const Point& a, const Point& b, double fa, double fb) const {
  const double w = b.u - a.u;
  const double secant =
      std::clamp(b.u - fb * w / (fb - fa), a.u + kMargin * w, b.u - kMargin * w);
  std::vector<double> us{secant};
  const int k = options_.bracket_points;
  for (int i = 1; i < k && static_cast<int>(us.size()) < Left(); ++i) {
    const double even = a.u + i * w / k;
    if (std::abs(even - secant) >= kMargin * w) us.push_back(even);
  }
  std::sort(us.begin(), us.end());
  return us;
}

OptimiserResult Search::Refine(Point a, Point b) {
  double fa = a.r(), fb = b.r();
  int kept = 0;  // +1: a kept repeatedly, −1: b kept repeatedly
  while (b.u - a.u > options_.unit_tolerance) {
    if (Budget()) return Finish(Termination::kBudget, "budget used up before a match within noise");
    std::vector<Point> ps;
    const std::vector<double> us = Round(a, b, fa, fb);
    if (us.size() == 1 ? !Eval(us[0], &ps.emplace_back()) : !EvalBatch(us, &ps)) {
      // Of several, those with a value still bound the crossing: the bracket only stays wider.
      std::erase_if(ps, [](const Point& p) { return !p.ok(); });
      if (ps.empty())
        return Finish(Termination::kFailed, "a candidate inside the bracket gave no value");
      failed_inside_ = true;
    }
    for (const Point& p : ps)
      if (p.settled) return Finish(Termination::kWithinNoise, "matched within noise");
    // The first candidate whose residual has the other sign than a's closes the bracket.
    size_t j = 0;
    while (j < ps.size() && ps[j].r() * fa >= 0) ++j;
    if (j == 0) {  // the crossing is in [a, p0]: a kept
      b = ps[0], fb = ps[0].r();
      if (kept == 1) fa *= 0.5;
      kept = 1;
    } else if (j == ps.size()) {  // in [p_last, b]: b kept
      a = ps.back(), fa = ps.back().r();
      if (kept == -1) fb *= 0.5;
      kept = -1;
    } else {  // between two new candidates: both ends new
      a = ps[j - 1], fa = a.r();
      b = ps[j], fb = b.r();
      kept = 0;
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
