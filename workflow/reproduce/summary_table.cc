#include "workflow/reproduce/summary_table.h"

#include <cmath>
#include <cstdio>

namespace demcal::workflow {
namespace {

std::string Number(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", v);
  return text;
}

nlohmann::ordered_json NumberOrNull(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

const std::vector<std::string>& ReferenceKeys() {
  static const std::vector<std::string> keys = {
      // stage 1: species
      "angle_BP_deg", "angle_TAED_deg", "angle_EP_deg", "clump_count_BP", "clump_count_TAED",
      "clump_count_EP", "aspect_ratio_BP", "aspect_ratio_TAED", "aspect_ratio_EP",
      // stage 2: Cohesion number
      "coh_coated_EP", "gamma_sim_J_m2",
      // stage 3 and 4: Γ per coating level and the curve
      "angle_EP_w0.5_deg", "gamma_w0.5_J_m2", "gamma_w2.5_J_m2",
      // stage 5: dissimilar pairs
      "gamma_EP_BP_J_m2", "gamma_EP_TAED_J_m2",
      // stage 6: segregation of the calibrated set
      "ep_cov_reduction_pct", "cov_EP_3d_uncoated", "cov_EP_3d_coated", "s_n_EP_3d_uncoated",
      "s_n_EP_3d_coated", "s_n_EP_front_uncoated", "s_n_EP_front_coated", "s_n_EP_back_uncoated",
      "s_n_EP_back_coated", "s_n_EP_3d_excessive", "cov_EP_3d_excessive", "cov_TAED_uncoated",
      "cov_TAED_coated", "cov_r_EP_3d", "cov_r_EP_front", "mixture_angle_uncoated_deg",
      "mixture_angle_coated_deg", "discharge_time_uncoated_s", "discharge_time_coated_s",
      "ep_outflow_fraction", "ep_impact_specific_kinetic_J_kg",
      "ep_landing_depth_uncoated_m", "ep_landing_depth_coated_m", "ep_landing_depth_excessive_m",
      "ep_after_impact_specific_kinetic_uncoated_J_kg",
      "ep_after_impact_specific_kinetic_coated_J_kg",
      "ep_after_impact_specific_kinetic_excessive_J_kg", "ep_bp_contacts_per_grain_uncoated",
      "ep_bp_contacts_per_grain_coated", "ep_bp_contacts_per_grain_excessive",
      "ep_axis_offset_uncoated", "ep_axis_offset_coated", "ep_axis_offset_excessive",
      // stage 7: fidelity check
      "fidelity_angle_shift_deg"};
  return keys;
}

VerdictKind ClassifyVerdict(const ReferenceValue& reference, const DemcalValue& value) {
  if (!std::isfinite(value.mean)) return VerdictKind::kNotRun;
  if (!value.comparable) return VerdictKind::kNotComparable;
  if (!std::isfinite(reference.value)) return VerdictKind::kDemcalOnly;
  if (reference.comparison == "at_least" || reference.comparison == "at_most") {
    const bool above = value.mean >= reference.value;
    const bool meets = reference.comparison == "at_least" ? above : !above;
    return meets ? VerdictKind::kMeets : VerdictKind::kDoesNotMeet;
  }
  const double sem = std::isfinite(value.sem) ? value.sem : 0;
  const double noise = std::sqrt(sem * sem + reference.uncertainty * reference.uncertainty);
  return std::fabs(value.mean - reference.value) <= noise ? VerdictKind::kWithinNoise
                                                          : VerdictKind::kDiffers;
}

std::string Verdict(const ReferenceValue& reference, const DemcalValue& value) {
  const VerdictKind kind = ClassifyVerdict(reference, value);
  const double sem = std::isfinite(value.sem) ? value.sem : 0;
  switch (kind) {
    case VerdictKind::kNotRun:
      return "not run: " +
             (value.note.empty() ? std::string("no value at this fidelity") : value.note);
    case VerdictKind::kNotComparable: return "not comparable: " + value.note;
    case VerdictKind::kDemcalOnly: return "demcal only (the paper gives a figure, no number)";
    case VerdictKind::kWithinNoise: return "within noise";
    case VerdictKind::kMeets:
    case VerdictKind::kDoesNotMeet: {
      const std::string sign = reference.comparison == "at_least" ? "≥ " : "≤ ";
      return std::string(kind == VerdictKind::kMeets ? "meets" : "does not meet") + " (" + sign +
             Number(reference.value) + (sem > 0 ? "; demcal ± " + Number(sem) : "") + ")";
    }
    case VerdictKind::kDiffers: break;
  }
  const double noise = std::sqrt(sem * sem + reference.uncertainty * reference.uncertainty);
  const double diff = value.mean - reference.value;
  std::string text = "differs by " + Number(diff) + " " + reference.unit;
  if (noise > 0) text += " (" + Number(diff / noise) + " σ)";
  else text += " (" + Number(100 * diff / reference.value) + " %; no noise to compare with)";
  return text;
}

std::string ShortVerdict(const SummaryRow& row) {
  if (row.kind == VerdictKind::kDemcalOnly) return "demcal only";
  if (row.note.empty()) return row.verdict;  // nothing below the table to point at
  if (row.kind == VerdictKind::kNotRun) return "not run";
  if (row.kind == VerdictKind::kNotComparable) return "not comparable";
  return row.verdict;
}

std::vector<SummaryRow> BuildSummaryRows(const std::vector<ReferenceValue>& reference,
                                         const DemcalValues& values) {
  std::vector<SummaryRow> rows;
  for (const ReferenceValue& r : reference) {
    SummaryRow row;
    row.key = r.key;
    row.quantity = r.quantity;
    row.unit = r.unit;
    row.source = r.source;
    row.comparison = r.comparison;
    row.paper_value = r.value;
    row.paper_uncertainty = r.uncertainty;
    DemcalValue v;
    if (auto it = values.find(r.key); it != values.end()) v = it->second;
    row.demcal_mean = v.mean;
    row.demcal_sem = v.sem;
    row.note = v.note;
    row.synthetic = v.synthetic;
    row.verdict = Verdict(r, v);
    row.kind = ClassifyVerdict(r, v);
    rows.push_back(row);
  }
  return rows;
}

nlohmann::ordered_json SummaryJson(const std::string& workflow_name, const std::string& fidelity,
                                   const std::vector<SummaryRow>& rows) {
  nlohmann::ordered_json out;
  out["format"] = "demcal-reproduce-summary/1";
  out["workflow"] = workflow_name;
  out["fidelity"] = fidelity;
  out["rows"] = nlohmann::ordered_json::array();
  for (const SummaryRow& r : rows) {
    out["rows"].push_back({{"key", r.key},
                           {"quantity", r.quantity},
                           {"unit", r.unit},
                           {"paper_value", NumberOrNull(r.paper_value)},
                           {"paper_uncertainty", r.paper_uncertainty},
                           {"comparison", r.comparison},
                           {"demcal_mean", NumberOrNull(r.demcal_mean)},
                           {"demcal_sem", NumberOrNull(r.demcal_sem)},
                           {"verdict", r.verdict},
                           {"note", r.note},
                           {"synthetic", r.synthetic},
                           {"source", r.source}});
  }
  return out;
}

}  // namespace demcal::workflow
