// Whole-study checks of a parsed study: a study that parses can still be one that never
// evaluates a candidate (a curve over a covariate some target lacks, a constraint its bounds or
// starts break) or that holds a parameter that never acts (a `when` no target meets, a pair
// property a curve overwrites). Each is refused at load, naming the field, instead of running
// to a `failed` end.
#include <algorithm>
#include <set>

#include "workflow/calibration/study_sections.h"

namespace demcal::workflow {
namespace {

std::string Field(const std::string& path) { return "field '" + path + "' "; }

// The conditions every candidate is evaluated under: the targets', and those of candidate
// targets that name one (the others read a target's runs).
std::vector<std::pair<std::string, calibrate::Condition>> EvaluatedConditions(const StudyFile& s) {
  std::vector<std::pair<std::string, calibrate::Condition>> out;
  for (const StudyTarget& t : s.targets)
    out.push_back({"target '" + t.target.name + "'", t.condition});
  for (const StudyCandidateTarget& t : s.candidate_targets)
    if (!t.condition.empty()) out.push_back({"candidate target '" + t.name + "'", t.condition});
  return out;
}

std::pair<std::string, std::string> Sorted(std::pair<std::string, std::string> pair) {
  if (pair.second < pair.first) std::swap(pair.first, pair.second);
  return pair;
}

// A curve needs its covariate, as a number its form accepts, under every evaluated condition,
// and its start coefficients must give a valid property there (the first candidate).
bool CheckCurves(const StudyFile& s, std::string* error) {
  const std::vector<double> start = s.space.Start();
  for (size_t c = 0; c < s.space.curves.size(); ++c) {
    const calibrate::ParameterCurve& curve = s.space.curves[c];
    for (const auto& [who, condition] : EvaluatedConditions(s)) {
      double w = 0, value = 0;
      std::string why;
      if (!curve.Covers(condition, &w, &why))
        return *error = Field(s.curve_paths[c] + ".covariate") + "'" + curve.covariate +
                        "' cannot be read for " + who + ": " + why + "; a curve needs its " +
                        "covariate as a number in the condition of every target", false;
      if (!curve.Evaluate(start, condition, &value, &why))
        return *error = Field(s.curve_paths[c] + ".coefficients") + "start values fail for " + who +
                        ": " + why + "; start the coefficients where the curve gives a valid " +
                        "value at every target's " + curve.covariate, false;
    }
  }
  return true;
}

// A parameter under `when` acts only on targets whose condition includes it.
bool CheckWhen(const StudyFile& s, std::string* error) {
  for (size_t k = 0; k < s.space.parameters.size(); ++k) {
    const calibrate::Parameter& p = s.space.parameters[k];
    if (p.curve >= 0 || p.when.empty()) continue;
    std::set<std::string> seen;
    bool acts = false;
    for (const auto& [who, condition] : EvaluatedConditions(s)) {
      acts = acts || calibrate::ConditionIncludes(condition, p.when);
      // (append, not "(" + string: GCC 12 gives a false -Wrestrict on that operator+)
      seen.insert(std::string("(").append(calibrate::DescribeCondition(condition)).append(")"));
    }
    if (acts) continue;
    std::string list;
    for (const std::string& c : seen) list += (list.empty() ? "" : ", ") + c;
    return *error = Field(s.parameter_paths[k] + ".when") + "(" +
                    calibrate::DescribeCondition(p.when) + ") is the condition of no target, so '" +
                    p.name + "' would never act; the targets' conditions: " + list, false;
  }
  return true;
}

// Parameters are written in order, curves after them: a parameter on the pair property of a
// later one that applies wherever it does (a curve, or a `when` it includes) is overwritten under
// every condition and never acts.
bool CheckOverwrites(const StudyFile& s, std::string* error) {
  const std::vector<calibrate::Parameter>& p = s.space.parameters;
  for (size_t k = 0; k < p.size(); ++k)
    for (size_t later = k + 1; later < p.size() && p[k].curve < 0; ++later)
      if (p[later].curve < 0 && p[later].property == p[k].property &&
          Sorted(s.parameter_materials[later]) == Sorted(s.parameter_materials[k]) &&
          calibrate::ConditionIncludes(p[k].when, p[later].when))
        return *error = Field(s.parameter_paths[k]) + "sets the pair property that '" +
                        p[later].name + "' (" + s.parameter_paths[later] + ") sets again " +
                        "wherever this one applies, so it would never act; drop it or put it " +
                        "after the more general one", false;
  for (size_t c = 0; c < s.space.curves.size(); ++c) {
    const calibrate::ParameterCurve& curve = s.space.curves[c];
    const auto pair = Sorted(s.curve_materials[c]);
    auto same = [&](calibrate::PairProperty property,
                    const std::pair<std::string, std::string>& m) {
      return property == curve.property && Sorted(m) == pair;
    };
    const std::string overwritten = "sets the pair property that the curve '" + curve.name +
                                    "' (" + s.curve_paths[c] + ") overwrites for every target, " +
                                    "so it would never act; keep one of the two";
    for (size_t k = 0; k < s.space.parameters.size(); ++k)
      if (s.space.parameters[k].curve < 0 &&
          same(s.space.parameters[k].property, s.parameter_materials[k]))
        return *error = Field(s.parameter_paths[k]) + overwritten, false;
    for (size_t e = 0; e < c; ++e)
      if (same(s.space.curves[e].property, s.curve_materials[e]))
        return *error = Field(s.curve_paths[e]) + overwritten, false;
  }
  return true;
}

// A chain must hold somewhere inside the bounds (each value at least the largest lower bound
// before it), and at the starts, the first candidate.
bool CheckChains(const StudyFile& s, std::string* error) {
  const std::vector<calibrate::Parameter>& p = s.space.parameters;
  for (size_t c = 0; c < s.space.non_decreasing.size(); ++c) {
    const std::vector<int>& chain = s.space.non_decreasing[c];
    const std::string at = Field(s.constraint_paths[c]);
    int floor = chain[0];
    for (int k : chain) {
      if (p[k].lower > p[floor].lower) floor = k;
      if (p[k].upper < p[floor].lower)
        return *error = at + "cannot hold within the bounds: '" + p[k].name + "' (max " +
                        FormatNumber(p[k].upper) + ") would have to be >= '" + p[floor].name +
                        "' (min " + FormatNumber(p[floor].lower) + ")", false;
    }
    for (size_t k = 1; k < chain.size(); ++k)
      if (p[chain[k]].start < p[chain[k - 1]].start)
        return *error = at + "the start values break it: '" + p[chain[k]].name + "' starts at " +
                        FormatNumber(p[chain[k]].start) + ", below '" + p[chain[k - 1]].name +
                        "' at " + FormatNumber(p[chain[k - 1]].start) + " (without 'start' a " +
                        "parameter starts at the middle of its bounds); give starts that rise " +
                        "along the list", false;
  }
  return true;
}

}  // namespace

bool CheckStudyEvaluable(const StudyFile& study, std::string* error) {
  return CheckCurves(study, error) && CheckWhen(study, error) &&
         CheckOverwrites(study, error) && CheckChains(study, error);
}

}  // namespace demcal::workflow
