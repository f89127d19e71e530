#pragma once
// The segregation heap's funnel and its orifice at a fidelity.
//
// A coarse-grained run (size ×s) has grains s times larger than the real ones. An orifice fixed
// in metres then passes a different flow at every fidelity: Beverloo's law,
//   W = C ρ_b √g (D − k d)^{5/2}
// (Beverloo, Leniger & van de Velde 1961, Chem. Eng. Sci. 15:260), depends on the grains only
// through the open width D − k d and the bulk density, and a uniform size scale leaves the bulk
// density unchanged. So the funnel meters the same flow at every fidelity when it holds the open
// width: D(s) = effective_orifice_diameter_m + beverloo_k · d_max(s).
//
// d is the feed's largest grain size at the run's fidelity, not a mean: the largest grains
// arch over the orifice first. For a clump it is the grain's mean caliper diameter (its width
// averaged over orientations, core/bodies/clump_size.h), for a sphere its diameter: an elongated
// grain tumbles through the orifice and blocks more of it than its sieve-equivalent sphere, and
// Beverloo's law with the equivalent diameter overestimates the flow of elongated grains
// (Mamtani 2011, MS thesis, University of Florida, who proposes a perimeter diameter, also an
// orientation-averaged size). k is not Beverloo's classical 1.5 for spheres: an orifice of 3 to
// 4 d_max in a slab barely wider than the orifice is near jamming, where the law holds only in
// form. The bundled 13 mm + 0.5 d_max passes through the two orifices measured to meter the
// same flow with the calibrated spheres (15.5 mm at size ×5, 10.3 g/s; 15 mm at ×4, 10.35 g/s);
// k 1.5 gave 12.5 mm at ×3, which metered only 6.35 g/s. Near jamming the flow depends on the
// grains' shape more than the mean caliper diameter carries: the rounder clumps of the clumps
// workflow pass the whole feed through this rule's orifice, so that workflow gives its own
// (workflow segregation.funnel_orifice, measured on its clumps; docs/experiments/segregation_funnel.md).
//
// The jam rule D > 3 d_max (segregation_experiment.cc, d_max the largest sieve-equivalent
// diameter) holds at every size scale as long as effective_orifice_diameter_m > 3 d_max −
// beverloo_k d: a rule that breaks it at the coarsest fidelity is refused there with both
// numbers named.
//
// Usage:
//   FunnelSettings f{.effective_orifice_diameter_m = 0.013, .beverloo_k = 0.5};
//   double d = f.OrificeDiameterM(FeedMaxMeanCaliperDiameter(model, feed));  // 15 mm at 4 mm

namespace demcal::objectives {

// The funnel above the box (assumed: the paper shows it in Fig. 1 without dimensions).
struct FunnelSettings {
  bool enabled = true;
  double orifice_diameter_m = 0.02;  // cut to the box depth by the front and back planes
  double top_diameter_m = 0.06;
  double height_m = 0.04;  // orifice to top
  // When > 0, the orifice follows the fidelity (the file comment) and orifice_diameter_m is
  // unused: D − k·d_max in metres, the width Beverloo's flow depends on.
  double effective_orifice_diameter_m = 0;
  double beverloo_k = 1.5;  // Beverloo's empty-annulus coefficient k (dimensionless)

  bool ScalesWithFidelity() const { return effective_orifice_diameter_m > 0; }
  // The orifice diameter in m for a feed whose largest grain is `max_grain_diameter_m`.
  double OrificeDiameterM(double max_grain_diameter_m) const;
};

}  // namespace demcal::objectives
