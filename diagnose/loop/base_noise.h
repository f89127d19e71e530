#pragma once
// BaseChi2: a base fit's χ² and its standard deviation due to the simulation noise of its
// predicted means, for the stagnation test of the base calibration (base_fit.h).
//
// The delta method of Chi2NoiseSd (evidence.h) without a floor weight: χ² = Σ r_i²,
// r_i = (m_i − y_i)/σ_i; an error δm_i of a simulated mean moves χ² by 2·r_i·δm_i/σ_i, so with
// independent means var χ² = Σ (2 r_i u_i)², u_i = sem_i/σ_i. Rows that read one simulated mean
// (one Observation::source, as the forward model numbers them: a scene shared by several table
// rows, the coating rows of a base model in which the coating changes nothing, run once) carry
// one error for all of them, so they add before squaring: var χ² = Σ_sources (Σ_{i∈source}
// 2 r_i u_i)². Counting them as independent underestimates the noise by up to √(rows per
// source) where their residuals share a sign, as they do on a base that misses the data in one
// direction. Measured on the weaker LIGGGHTS adhesion case (docs/diagnose/base_fit.md): over 14
// pairs of base candidates 0.0016 to 0.005 apart in μs, χ² differed by an sd of 19.5; the
// independent rows gave a median 13.0, the grouped rows 18.6.
//
//   const NoisyChi2 c = BaseChi2(WithPrediction(observations, prediction, floor_factor));
//
// Thread-safety: a pure function.
#include <cmath>
#include <vector>

#include "diagnose/gap/observation.h"

namespace demcal::diagnose {

struct NoisyChi2 {
  double chi2 = INFINITY, noise_sd = 0;
};

// at: the observations with the prediction (and its sources) filled in (WithPrediction).
NoisyChi2 BaseChi2(const std::vector<Observation>& at);

}  // namespace demcal::diagnose
