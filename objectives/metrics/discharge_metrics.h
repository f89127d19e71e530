#pragma once
// Funnel discharge metrics from the mass that has left the funnel over time (Alizadeh et al. 2018,
// Powder Technol. 339:789-800, section 3.3 and Fig. 16): the discharge (emptying) time, the steady
// mass flow rate with its standard error, and the outflow composition per species in time bins
// (pre-segregation in the funnel shows as a drift of these fractions). Pure function, SI units,
// thread-safe.
//
//   std::vector<OutflowSample> s = ...;  // cumulative discharged mass per species, by time
//   DischargeMetrics m = AnalyseDischarge(s, /*gate_open_s=*/0.5, {});
//   if (m.ok) std::printf("%.3f kg/s, emptied in %.2f s\n", m.mass_flow_kg_s, m.discharge_time_s);
#include <string>
#include <vector>

namespace demcal::objectives {

struct OutflowSample {
  double time_s = 0;
  std::vector<double> cumulative_mass_kg;  // per species, mass that has left the funnel by time_s
};

struct DischargeOptions {
  double discharge_fraction = 0.99;  // the discharge ends when this fraction of the mass is out
  double flow_window_low = 0.2;      // steady flow fitted between these fractions of the mass
  double flow_window_high = 0.8;
  int composition_bins = 20;     // equal bins from the gate opening to the discharge end
  double composition_bin_s = 0;  // > 0: fixed bin width instead (the last bin is clipped)
  // > 0: the mass filled into the funnel; the outflow must reach discharge_fraction of it. 0: the
  // mass out by the last sample is taken as the whole (the run must last until the funnel is
  // empty).
  double expected_total_mass_kg = 0;

  bool IsValid(std::string* error) const;
};

struct CompositionBin {
  double t_start_s = 0, t_end_s = 0;
  std::vector<double> mass_fraction;  // per species; all 0 when nothing left during the bin
  double mass_kg = 0;                 // mass out during the bin
};

struct DischargeMetrics {
  bool ok = false;
  std::string message = "not analysed";
  double discharge_time_s = 0;    // gate opening → discharge_fraction of the total mass out
  double mass_flow_kg_s = 0;      // least-squares slope of mass vs time inside the flow window
  double mass_flow_sem_kg_s = 0;  // its standard error (residuals of a cumulative curve are
                                  // correlated, so read it as a lower bound)
  double total_mass_kg = 0;       // discharged after the gate opened (or expected_total_mass_kg)
  // The fitted steady line, discharged mass = intercept + rate · (t − gate_open_s), over the
  // times of the first and last fitted samples (for plots).
  double mass_flow_intercept_kg = 0;
  double flow_window_start_s = 0, flow_window_end_s = 0;
  std::vector<CompositionBin> composition;
};

// Samples in increasing time, every one with the same number of species; cumulative masses
// non-decreasing. Mass out before gate_open_s is not counted.
DischargeMetrics AnalyseDischarge(const std::vector<OutflowSample>& samples, double gate_open_s,
                                  const DischargeOptions& options);

}  // namespace demcal::objectives
