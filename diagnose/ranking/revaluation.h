#pragma once
// Re-valuation: whether the best-ranked effect adds a mechanism the base model lacks, or only
// re-values a parameter the base model already has (a model-form matter, not a missing effect).
//
// An effect whose base model already carries the mechanism (EffectParameter::assumed > 0: the
// base's μr for Δμr, its wall friction for Δμw, its size width for Δwidth) and whose refit
// changes it by no more than that assumed amount, |Δ| ≤ assumed, says "the value assumed for a
// modelled parameter is off by less than itself": any amount less (down to none), or up to
// twice as much. The data cannot tell that from a model-form offset in the law of that very
// mechanism: another engine's rolling law with a "torque-equivalent" coefficient, a lab
// powder's rolling behaviour that no constant-torque law reproduces, a wall finish. Each of
// those moves the *effective* value of the modelled parameter by its own order, and every such
// offset fits the data as well as a real change of the powder would, so naming it a missing
// effect would be a confident wrong answer whenever the base model's law is not the data's.
// Such a winner is answered `model_form_offset` with the re-valuation stated (the parameter,
// its signed value, the fit it gives) and the advice to calibrate that parameter in the base.
//
// Why |Δ| ≤ assumed, and not some other multiple: it is the one scale-free amount every
// modelled parameter carries (its own assumed value), and it draws the line where the
// assumption stops having the right order of magnitude: a mechanism more than twice as strong
// as modelled, or switched on where the base has none (assumed 0: adhesion on a cohesionless
// base, shape on spheres), is more than a re-valuation and is named. A change below the
// assumed value has the sign "less than assumed": less of a mechanism the model already has is,
// by definition, never a *missing* mechanism. No diagnosis result set the line.
//
// Thread-safety: pure functions.
#include <string>
#include <vector>

#include "diagnose/effects/effect.h"

namespace demcal::diagnose {

// True when `value` of `p` re-values a modelled parameter: p.assumed > 0 and |value| ≤ assumed.
bool IsRevaluation(const EffectParameter& p, double value);

// Two effects not told apart, `first` (the better fit) at `first_value` and `second` at
// `second_value`: which of them, if either, makes the answer a re-valuation rather than "not
// told apart". 0: the first, when it re-values a modelled parameter and the second re-values
// one too (both say "an assumed value is off"); 0 or 1: the one that is *less* of a modelled
// mechanism than assumed (IsRevaluation, value < 0) when the other adds a mechanism; −1: the
// tie stays. Why the second case, either way round: another engine's law or a real powder's
// behaviour makes an offset in what the model has about certain, a missing mechanism only
// possible, so an added mechanism is named (or offered as one of two) only when it fits
// better than "less of what the model has" by more than the tie margin; it is tried again with
// the re-valued parameter in the fit, where it must explain what the offset leaves
// (diagnosis.h). A re-valuation that is *more* of a modelled mechanism (up to twice), tied with
// an added one, stays a tie: that is what a missing mechanism acting the same way looks like
// (elongated grains steepen a heap as more rolling resistance does).
int RevaluationOfTie(const EffectParameter& first, double first_value,
                     const EffectParameter& second, double second_value);

// "less rolling resistance than assumed: delta_mu_r = -0.063 against the assumed 0.1 (chi2/dof
// 0.23 with it)": the re-valuation in words.
std::string RevaluationText(const std::string& key, const EffectParameter& p, double value,
                            double chi2_per_dof);

}  // namespace demcal::diagnose
