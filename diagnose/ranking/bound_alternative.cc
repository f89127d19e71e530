#include "diagnose/ranking/bound_alternative.h"

namespace demcal::diagnose {

std::string BoundVerdictName(BoundVerdict v) {
  switch (v) {
    case BoundVerdict::kNotJudged:
      return "not_judged";
    case BoundVerdict::kNoEffectInside:
      return "no_effect_inside";
    case BoundVerdict::kNotToldApart:
      return "not_told_apart";
    case BoundVerdict::kEffect:
      return "effect";
    case BoundVerdict::kBeyondRange:
      return "beyond_range";
    case BoundVerdict::kOutranked:
      return "outranked";
  }
  return "not_judged";
}

BoundJudgement JudgeBound(const std::vector<RankingEntry>& entries, const std::vector<bool>& inside,
                          const std::vector<bool>& copies_bound, const Evidence& base) {
  BoundJudgement j;
  const Evidence* a = &base;
  for (size_t i = 0; i < entries.size(); ++i) {
    const RankingEntry& e = entries[i];
    if (e.simulated && i < copies_bound.size() && copies_bound[i] && BicGap(e.evidence, *a) < 0) {
      a = &e.evidence;
      j.alternative = static_cast<int>(i);
    }
  }
  for (size_t i = 0; i < entries.size(); ++i) {
    const RankingEntry& e = entries[i];
    if (!e.simulated || e.control || i >= inside.size() || !inside[i]) continue;
    if (j.effect < 0 || e.evidence.delta_bic < entries[j.effect].evidence.delta_bic)
      j.effect = static_cast<int>(i);
  }
  if (j.effect < 0) return j.verdict = BoundVerdict::kNoEffectInside, j;
  const Evidence& e = entries[j.effect].evidence;
  j.bic_gap = BicGap(e, *a);
  j.within = IndistinctWithin(e, *a);
  if (j.bic_gap <= -j.within && e.significant)
    j.verdict = BoundVerdict::kEffect;
  else if (j.bic_gap <= 0)
    j.verdict = BoundVerdict::kNotToldApart;
  else
    j.verdict = BoundVerdict::kBeyondRange;
  if (j.verdict != BoundVerdict::kNotToldApart) return j;
  for (size_t i = 0; i < entries.size(); ++i) {  // a fit clearly better than both (header)
    const RankingEntry& w = entries[i];
    if (!w.simulated || w.control || !w.evidence.significant || static_cast<int>(i) == j.effect)
      continue;
    if (BicGap(w.evidence, e) <= -IndistinctWithin(w.evidence, e) &&
        BicGap(w.evidence, *a) <= -IndistinctWithin(w.evidence, *a) &&
        (j.outranked_by < 0 || w.evidence.delta_bic < entries[j.outranked_by].evidence.delta_bic))
      j.outranked_by = static_cast<int>(i);
  }
  if (j.outranked_by >= 0) j.verdict = BoundVerdict::kOutranked;
  return j;
}

}  // namespace demcal::diagnose
