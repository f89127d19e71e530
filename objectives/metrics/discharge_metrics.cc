#include "objectives/metrics/discharge_metrics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "objectives/metrics/line_fit.h"

namespace demcal::objectives {

bool DischargeOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& what) {
    if (error) *error = "DischargeOptions: " + what;
    return false;
  };
  if (!(discharge_fraction > 0 && discharge_fraction <= 1))
    return fail("discharge_fraction must be in (0, 1]");
  if (!(flow_window_low >= 0 && flow_window_low < flow_window_high && flow_window_high <= 1))
    return fail("need 0 <= flow_window_low < flow_window_high <= 1");
  if (composition_bins < 1) return fail("composition_bins must be >= 1");
  if (!(composition_bin_s >= 0 && std::isfinite(composition_bin_s)))
    return fail("composition_bin_s must be >= 0");
  if (!(expected_total_mass_kg >= 0 && std::isfinite(expected_total_mass_kg)))
    return fail("expected_total_mass_kg must be >= 0");
  return true;
}

namespace {

double Total(const OutflowSample& s) {
  return std::accumulate(s.cumulative_mass_kg.begin(), s.cumulative_mass_kg.end(), 0.0);
}

// Empty when the samples are usable, else what is wrong with them.
std::string SampleProblem(const std::vector<OutflowSample>& samples, double gate_open_s) {
  if (samples.size() < 2) return "need at least 2 outflow samples";
  const size_t species = samples[0].cumulative_mass_kg.size();
  if (species == 0) return "outflow samples have no species";
  if (!std::isfinite(gate_open_s) || gate_open_s >= samples.back().time_s)
    return "gate_open_s must be finite and before the last sample";
  for (size_t i = 0; i < samples.size(); ++i) {
    const OutflowSample& s = samples[i];
    const std::string where = " at sample " + std::to_string(i);
    if (s.cumulative_mass_kg.size() != species) return "species count changes" + where;
    if (!std::isfinite(s.time_s)) return "non-finite time" + where;
    if (i > 0 && !(s.time_s > samples[i - 1].time_s)) return "times not increasing" + where;
    for (size_t k = 0; k < species; ++k) {
      const double m = s.cumulative_mass_kg[k];
      if (!std::isfinite(m) || m < 0) return "negative or non-finite mass" + where;
      if (i > 0 && m < samples[i - 1].cumulative_mass_kg[k])
        return "cumulative mass decreases" + where;
    }
  }
  return "";
}

// Linear interpolation of value(sample) at time t, held constant outside the sampled range.
template <typename Value>
double At(const std::vector<OutflowSample>& samples, double t, Value value) {
  if (t <= samples.front().time_s) return value(samples.front());
  for (size_t i = 1; i < samples.size(); ++i) {
    if (t > samples[i].time_s) continue;
    const double w = (t - samples[i - 1].time_s) / (samples[i].time_s - samples[i - 1].time_s);
    return value(samples[i - 1]) + w * (value(samples[i]) - value(samples[i - 1]));
  }
  return value(samples.back());
}

// First time the discharged mass reaches `mass_kg` (samples before the gate are skipped).
double TimeReaching(const std::vector<OutflowSample>& samples, double gate_open_s, double m0,
                    double mass_kg) {
  double t_prev = gate_open_s, m_prev = 0;
  for (const OutflowSample& s : samples) {
    if (s.time_s <= gate_open_s) continue;
    const double m = Total(s) - m0;
    if (m >= mass_kg) return t_prev + (mass_kg - m_prev) / (m - m_prev) * (s.time_s - t_prev);
    t_prev = s.time_s;
    m_prev = m;
  }
  return samples.back().time_s;
}

std::vector<CompositionBin> Composition(const std::vector<OutflowSample>& samples, double t0,
                                        double t1, const DischargeOptions& options) {
  const double width = options.composition_bin_s > 0 ? options.composition_bin_s
                                                     : (t1 - t0) / options.composition_bins;
  const size_t species = samples[0].cumulative_mass_kg.size();
  std::vector<CompositionBin> bins;
  for (int i = 0; t0 + i * width < t1 - 1e-9 * width; ++i) {
    const double start = t0 + i * width;
    CompositionBin bin{start, std::min(start + width, t1), std::vector<double>(species, 0), 0};
    for (size_t k = 0; k < species; ++k) {
      auto species_mass = [k](const OutflowSample& s) { return s.cumulative_mass_kg[k]; };
      bin.mass_fraction[k] =
          At(samples, bin.t_end_s, species_mass) - At(samples, bin.t_start_s, species_mass);
      bin.mass_kg += bin.mass_fraction[k];
    }
    if (bin.mass_kg > 0)
      for (double& f : bin.mass_fraction) f /= bin.mass_kg;
    else
      std::fill(bin.mass_fraction.begin(), bin.mass_fraction.end(), 0.0);
    bins.push_back(std::move(bin));
  }
  return bins;
}

// Least-squares mass flow over the samples inside the flow window; false with the reason.
bool SteadyFlow(const std::vector<OutflowSample>& samples, double gate_open_s, double m0,
                const DischargeOptions& options, DischargeMetrics* result) {
  std::vector<double> t, m;
  for (const OutflowSample& s : samples) {
    const double out = Total(s) - m0;
    if (s.time_s < gate_open_s || out < options.flow_window_low * result->total_mass_kg ||
        out > options.flow_window_high * result->total_mass_kg)
      continue;
    t.push_back(s.time_s - gate_open_s);
    m.push_back(out);
  }
  const LineFit fit = FitLine(t, m);
  if (t.size() < 3 || !fit.ok) {
    result->message = std::to_string(t.size()) +
                      " samples inside the flow window (need 3): sample the outflow more often";
    return false;
  }
  result->mass_flow_kg_s = fit.slope;
  result->mass_flow_sem_kg_s = fit.slope_sem;
  result->mass_flow_intercept_kg = fit.intercept;
  result->flow_window_start_s = t.front() + gate_open_s;
  result->flow_window_end_s = t.back() + gate_open_s;
  return true;
}

}  // namespace

DischargeMetrics AnalyseDischarge(const std::vector<OutflowSample>& samples, double gate_open_s,
                                  const DischargeOptions& options) {
  DischargeMetrics result;
  std::string problem;
  if (options.IsValid(&problem)) problem = SampleProblem(samples, gate_open_s);
  if (!problem.empty()) {
    result.message = problem;
    return result;
  }
  const double m0 = At(samples, gate_open_s, Total);
  const double out = Total(samples.back()) - m0;
  result.total_mass_kg = options.expected_total_mass_kg > 0 ? options.expected_total_mass_kg : out;
  if (!(out > 0)) {
    result.message = "no mass left the funnel after the gate opened";
    return result;
  }
  const double end_mass = options.discharge_fraction * result.total_mass_kg;
  if (out < end_mass) {
    result.message = "discharge incomplete: " + std::to_string(out) + " of " +
                     std::to_string(result.total_mass_kg) + " kg out by the last sample";
    return result;
  }
  const double t_end = TimeReaching(samples, gate_open_s, m0, end_mass);
  result.discharge_time_s = t_end - gate_open_s;
  if (!SteadyFlow(samples, gate_open_s, m0, options, &result)) return result;
  result.composition = Composition(samples, gate_open_s, t_end, options);
  result.ok = true;
  result.message = "ok";
  return result;
}

}  // namespace demcal::objectives
