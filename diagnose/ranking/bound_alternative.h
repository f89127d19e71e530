#pragma once
// JudgeBound: a base fit that ends on a bound of its study's range, against the candidate
// effects whose refits let that parameter back inside (docs/diagnose/base_fit.md, "A base
// parameter fitted onto a bound"). A fit on a bound may be the data asking for the parameter
// beyond the range (the range was too narrow, or a model-form offset the parameter absorbs),
// or an effect that moves the observables the same way and was absorbed there (LIGGGHTS data
// with less rolling resistance pull a μs-only base to its lower bound). Two explanations, one
// verdict:
//  - the bound alternative A: the better, by BicGap (evidence.h), of the base at its bound
//    and the simulated refit of the control that copies the bound parameter (it may step
//    beyond the range; no extra parameter for the base, one for the control);
//  - the best effect E (lowest ΔBIC) among the simulated, non-control refits that put every
//    bound parameter strictly inside its range.
// With the ranking's own rules (BicGap; ToldApart's margin max(kBicIndistinct, kNoiseSds noise
// sd)), the verdict is
//  - kEffect: E is significant (evidence.h, α/K) and better than A beyond the tie margin:
//    the evidence rules the bound alternative out, and the ranking's winner stands;
//  - kNotToldApart: E fits at least as well as A, its BIC penalty included (BicGap ≤ 0), but
//    not beyond the margin, or not significantly against the base: "not told apart: the
//    parameter beyond its range, or E". At least as well, not merely within the margin: a base
//    whose truth lies on the bound with nothing missing has every effect within the margin of
//    it (an extra parameter always fits a little), and would always be "not told apart";
//    an effect must earn its parameter (Δχ² ≥ ln n, Schwarz) to stand beside the bound;
//  - kBeyondRange: no effect with the parameter inside fits as well as A: the data may ask for
//    the parameter beyond the range (widen it); no effect is suggested;
//  - kNoEffectInside: no simulated effect refit left the bound.
// A tie between A and E is the answer only when nothing fits clearly better than both: when a
// significant simulated effect refit W (on the bound or not) beats both A and E beyond the tie
// margin, the verdict is kOutranked and the ranking goes on as usual (W is what it names; the
// base parameter stays on its bound with W). The cross-engine `wide_psd` case on demcal's `cdt`:
// μs on its lower bound, the size width's refit (still on it) ΔBIC −43.8, the bound alternative
// and the best effect held inside (less rolling resistance, χ²/dof 5.0) 5.9 apart — "not told
// apart" between two fits both far worse than the hidden effect's.
// The control is never named (the control guard): it only stands for "beyond the range".
//
//   BoundJudgement j = JudgeBound(entries, inside, copies_bound, base_evidence);
//
// Thread-safety: pure function.
#include <string>
#include <vector>

#include "diagnose/ranking/evidence.h"
#include "diagnose/ranking/ranking.h"

namespace demcal::diagnose {

enum class BoundVerdict {
  kNotJudged,
  kNoEffectInside,
  kNotToldApart,
  kEffect,
  kBeyondRange,
  kOutranked
};

std::string BoundVerdictName(BoundVerdict v);  // "not_told_apart", "effect", ...

struct BoundJudgement {
  BoundVerdict verdict = BoundVerdict::kNotJudged;
  int effect = -1;        // entry index of E (−1: none)
  int alternative = -1;   // entry index of the control's refit standing for A; −1: the base
  double bic_gap = 0;     // BicGap(E, A): negative favours E
  double within = 0;      // IndistinctWithin(E, A): the tie margin
  int outranked_by = -1;  // kOutranked: entry index of W
};

// entries: the step's ranking entries; inside[i]: entry i's simulated refit has every bound
// parameter strictly inside its range; copies_bound[i]: entry i is the control copying a bound
// parameter; base: the base fit's own evidence (its residuals, q, floor, χ² noise; penalty 0).
BoundJudgement JudgeBound(const std::vector<RankingEntry>& entries, const std::vector<bool>& inside,
                          const std::vector<bool>& copies_bound, const Evidence& base);

}  // namespace demcal::diagnose
