#pragma once
// BaseChi2: a base fit's χ² and its standard deviation due to the simulation noise of its
// predicted means, for the stagnation test of the base calibration (base_fit.h).
//
// The delta method of Chi2NoiseSd (evidence.h): χ² = Σ r_i², r_i = (m_i − y_i)/σ_i; an error δm_i
// of a simulated mean moves χ² by 2·r_i·δm_i/σ_i, so with independent means var χ² = Σ (2 r_i u_i)²,
// u_i = sem_i/σ_i. Rows that read one simulated mean are not independent: a scene shared by
// several table rows (the coating rows of a base model in which the coating changes nothing are
// one simulated heap, "run once") carries one error for all of them, which moves their terms
// together, so they add before squaring: var χ² = Σ_groups (Σ_{i∈group} 2 r_i u_i)². Counting them
// as independent underestimates the noise by up to √(rows per group) where their residuals share
// a sign, as they do on a base that misses the data in one direction. Measured on the weaker
// LIGGGHTS adhesion case (docs/diagnose/base_fit.md): over 14 pairs of base candidates 0.0016 to
// 0.005 apart in μs, χ² differed by an sd of 19.5; the independent rows gave a median 13.0, the
// grouped rows 18.6.
//
// A group is the rows whose prediction is the same simulated quantity: equal mean, standard
// error and single-run scatter (bit for bit; two observables or two scenes do not share all
// three by chance). A row with sem 0 (no simulation noise) is its own group.
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

// at: the observations with the prediction filled in (WithPrediction).
NoisyChi2 BaseChi2(const std::vector<Observation>& at);

}  // namespace demcal::diagnose
