#pragma once
// Random-mixture reference CoV_r (Alizadeh et al. 2018, Eq. 6 and the text around it): the CoV a
// perfectly random mixture of the same mean composition would show in the same bins. Each bin's
// fraction is drawn from the binomial sampling distribution of a random mixture, mean P and
// σ_R = sqrt(P(1 − P)/N) (Eq. 6), N = number of granules the bin holds; the CoV of the drawn
// fractions (Eq. 5, same estimator as CoV_m) is averaged over repetitions (the paper: 100 in
// Excel).
//
// N per bin (Eq. 6's N): the paper takes bin volume × 0.6 loose packing / volume of one granule of
// the species, with smaller N for the partly filled corner and edge bins. Here the filled volume of
// a bin is the solid volume of its grains / packing (FilledVolumeM3): it needs no reconstruction of
// the heap surface, follows the real fill of every partial bin, and for a full bin packed at 0.6
// equals the paper's bin volume. N = filled × packing / granule volume (GrainsPerBin). A caller
// with another filled volume (e.g. the bin area under the surface × depth) passes its own N.
//
// Pure functions; deterministic from the seed (core::Rng with its own Gaussian and binomial
// samplers, so results do not depend on the standard library). Usage:
//   auto n = GrainsPerBin(filled_volumes_m3, granule_volume_m3, 0.6);
//   auto ref = RandomMixtureCoV(p, n, {.repetitions = 100, .seed = 7}, &error);
//   double s_n = cov_m / ref->cov_r;   // Eq. 7
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace demcal::objectives {

enum class RandomDraw {
  kNormal,    // fraction ~ Normal(P, σ_R), as the paper did in Excel (may fall below 0)
  kBinomial,  // fraction = Binomial(n, P)/n with n = round(N) (at least 1): exact for equal grains
};

struct RandomMixtureOptions {
  int repetitions = 100;  // Monte Carlo repetitions (the paper: 100)
  uint64_t seed = 1;
  RandomDraw draw = RandomDraw::kNormal;
  bool IsValid(std::string* error) const;
};

struct RandomMixtureCov {
  double cov_r = 0;           // mean CoV over the repetitions
  double standard_error = 0;  // Monte Carlo standard error of cov_r (std of the CoVs / sqrt(reps))
  int repetitions_used = 0;   // repetitions whose drawn fractions had a positive mean
};

// Filled volume of a bin from the solid volume of its grains: solid / packing_fraction.
double FilledVolumeM3(double solid_volume_m3, double packing_fraction = 0.6);

// N per bin = filled volume × packing_fraction / granule volume (Eq. 6's N).
std::vector<double> GrainsPerBin(const std::vector<double>& filled_volumes_m3,
                                 double granule_volume_m3, double packing_fraction = 0.6);

// Monte Carlo CoV_r for mean fraction p in (0, 1) and N per bin (each > 0, at least 2 bins).
// Repetitions whose drawn fractions have a non-positive mean (possible for binomial draws of a
// rare species) have no CoV and are skipped; nullopt and a message if none is left.
std::optional<RandomMixtureCov> RandomMixtureCoV(double p,
                                                 const std::vector<double>& grains_per_bin,
                                                 const RandomMixtureOptions& options,
                                                 std::string* error);

// Eq. 6 divided by P: σ_R/P = sqrt((1 − P)/(P N)), the population CoV for equal bins of N grains.
double AnalyticRandomCoV(double p, double grains_per_bin);

}  // namespace demcal::objectives
