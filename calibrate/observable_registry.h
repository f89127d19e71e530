#pragma once
// The observables a study can fit, by name: unit, the physically possible range (a measurement
// or simulated value outside it is refused as bad data, never calibrated to) and what it is.
// A virtual experiment (an ExperimentProbe, experiment_probe.h) declares which of these names it
// measures. Adding an observable is one line in observable_registry.cc plus the probe that
// measures it.
//
//   const ObservableInfo* info = FindObservable("angle_deg");
//   if (!info || !info->Contains(value)) ...;
//
// Thread-safety: immutable static data.
#include <string>
#include <vector>

namespace demcal::calibrate {

struct ObservableInfo {
  std::string name;   // "angle_deg": the unit is part of the name
  std::string unit;   // "deg"
  double min = 0;     // physically possible range, inclusive
  double max = 0;
  std::string what;   // one line for tables and --help
  bool Contains(double value) const { return value >= min && value <= max; }
  std::string RangeText() const;  // "[0, 90] deg"
  // The smallest uncertainty a measurement of it may state (limits::kMinUncertaintyFraction of
  // the span), and the allowed interval as text: "[9e-08, 90] deg".
  double MinUncertainty() const;
  std::string UncertaintyRangeText() const;
};

const std::vector<ObservableInfo>& RegisteredObservables();
const ObservableInfo* FindObservable(const std::string& name);
std::vector<std::string> ObservableNames();

}  // namespace demcal::calibrate
