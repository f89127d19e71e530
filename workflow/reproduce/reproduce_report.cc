#include "workflow/reproduce/reproduce_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "outputs/html_report.h"
#include "workflow/reproduce/clump_table.h"
#include "workflow/reproduce/report_headline.h"
#include "workflow/reproduce/reproduce_plots.h"

namespace demcal::workflow {
namespace {

// j[key], or null when j is not an object or lacks the key (a skipped or failed stage).
const nlohmann::json& At(const nlohmann::json& j, const char* key) {
  static const nlohmann::json kNull;
  return j.is_object() && j.contains(key) ? j[key] : kNull;
}

std::string Fmt(double v, const char* format = "%.3g") {
  if (!std::isfinite(v)) return "–";
  char text[48];
  std::snprintf(text, sizeof(text), format, v);
  return text;
}
std::string Fmt(const nlohmann::json& j, const char* format = "%.3g") {
  return j.is_number() ? Fmt(j.get<double>(), format) : "–";
}
std::string PlusMinus(const nlohmann::json& mean, const nlohmann::json& sem, const char* f = "%.3g") {
  return Fmt(mean, f) + (sem.is_number() ? " ± " + Fmt(sem, f) : "");
}

// The numbers of the figures that lead the report (0: not drawn), for the sections they belong to.
struct KeyFigures {
  int gamma_curve = 0, angle = 0, bars = 0;
};

std::string Duration(double seconds) {
  return seconds < 120 ? Fmt(seconds, "%.0f") + " s" : Fmt(seconds / 60, "%.0f") + " min";
}

// "Figure 2 (in the verdict, at the top) ..." for a section whose plot leads the report; nothing
// when the plot was not drawn.
void SeeFigure(int number, const std::string& what, HtmlReport* r) {
  if (number > 0)
    r->Paragraph("Figure " + std::to_string(number) + " (at the top, with the verdict) " + what +
                 ".");
}

bool AnySynthetic(const nlohmann::json& items) {
  bool synthetic = false;
  for (const auto& [key, item] : items.items())
    synthetic = synthetic || item.value("synthetic", false);
  return synthetic;
}

// The run itself: which workflow, at which fidelity, how long its stages took.
HeadlineItem RunLine(const ReportInputs& in) {
  double seconds = 0;
  for (const auto& [stage, s] : in.timings->items())
    if (s.is_number()) seconds += s.get<double>();
  return {.label = "Run:",
          .text = in.workflow->name + " at the " +
                  (in.quick ? "--quick fidelity (coarser heaps, fewer replicates: a first look)"
                            : "default fidelity") +
                  ", " + std::to_string(in.timings->size()) + " stages in " + Duration(seconds) +
                  " of wall time"};
}

// The verdict first: the headline lines, then the key figures side by side (Γ(w), the angle
// against the coating, the segregation indices); their numbers go to *key for the sections.
bool VerdictSection(const ReportInputs& in, const RowNotes& notes, HtmlReport* r,
                    KeyFigures* key, std::string* error) {
  r->Section("Verdict");
  std::vector<HeadlineItem> lines = {RunLine(in)};
  for (HeadlineItem& line : VerdictHeadline(*in.rows, notes)) lines.push_back(std::move(line));
  r->Headline(lines);
  const std::string m = in.workflow->coating.material;
  std::vector<HtmlFigure> figures;
  int next = r->figure_count() + 1;
  auto add = [&](const std::string& svg, const std::string& caption, bool synthetic, int* number) {
    if (svg.empty()) return;
    figures.push_back({.svg_document = svg, .caption = caption, .synthetic = synthetic});
    *number = next++;
  };
  add(GammaCurveSvg(*in.results), "Γ against coating level, fitted curve and 1σ band",
      At(*in.results, "gamma_curve").value("synthetic", false), &key->gamma_curve);
  add(AngleVsCoatingSvg(*in.results, m),
      "repose angle against coating: measured (and synthetic) against demcal",
      AnySynthetic(At(At(*in.results, "gamma_per_coating"), "levels")), &key->angle);
  add(SegregationBarsSvg(*in.results, m), m + " CoV and S_n per scenario ± sem",
      AnySynthetic(At(At(*in.results, "segregation"), "scenarios")), &key->bars);
  return r->FigureRow(figures, error);
}

// The whole table with short verdicts, coloured by kind; each distinct note once, below it.
bool SummarySection(const ReportInputs& in, const RowNotes& notes, HtmlReport* r,
                    std::string* error) {
  r->Section("Paper against demcal");
  r->Paragraph("Workflow " + in.workflow->name + " (" + in.workflow->source + ") at the " +
               (in.quick ? "--quick" : "default") + " fidelity. Verdicts: 'within noise' when "
               "|demcal − paper| ≤ √(sem² + u²) (the calibration's criterion); otherwise the "
               "difference in units of that noise; 'meets' or 'does not meet' for an at-least or "
               "at-most number; 'demcal only' where the paper shows a figure without a number. "
               "The numbered notes below the table say how a number was obtained, why it differs "
               "where that is known, or why it was not run. Rows marked synthetic rest on the "
               "synthetic coating angles (datasets/synthetic/alizadeh2018_coating_angles/), not "
               "on measurements.");
  HtmlTable t{.caption = "summary.json",
              .header = {"quantity", "paper", "demcal mean ± sem", "verdict", "source"},
              .tone_column = 3,
              .row_notes = notes.row_notes,
              .note_column = 3};
  for (const SummaryRow& row : *in.rows) {
    t.rows.push_back({row.quantity + " [" + row.unit + "]",
                      (row.comparison == "at_least" ? "≥ " : row.comparison == "at_most" ? "≤ " : "") +
                          Fmt(row.paper_value),
                      Fmt(row.demcal_mean) + (std::isfinite(row.demcal_sem) ? " ± " + Fmt(row.demcal_sem) : ""),
                      ShortVerdict(row), row.source});
    t.synthetic_rows.push_back(row.synthetic);
    t.row_tones.push_back(VerdictTone(row.kind));
  }
  if (!r->Table(t, error)) return false;
  if (!notes.notes.empty()) r->Footnotes(notes.notes);
  return true;
}

// A calibration's termination, and where its value is the line through the candidates around
// the crossing (calibrate/local_crossing.h), so.
std::string TerminationText(const nlohmann::json& o) {
  return o.value("termination", "") +
         (o.value("by_line", false) ? "; value: the line through the candidates around the crossing"
                                    : "");
}

bool SpeciesSection(const ReportInputs& in, HtmlReport* r, std::string* error) {
  const nlohmann::json& s = At(At(*in.results, "species"), "species");
  r->Section("1. Species");
  r->Paragraph("Shape assumption: " + in.workflow->shape_assumption);
  HtmlTable t{.caption = "friction calibrated to each measured repose angle",
              .header = {"species", "property", "value ± σ", "angle measured [deg]",
                         "angle demcal [deg]", "termination", "outputs"}};
  for (const auto& [name, o] : s.items())
    t.rows.push_back({name, o.value("property", ""), PlusMinus(At(o, "value"), At(o, "sigma")),
                      PlusMinus(At(o, "measured"), At(o, "uncertainty"), "%.1f"),
                      PlusMinus(At(o, "simulated"), At(o, "sem"), "%.1f"), TerminationText(o),
                      o.value("result_dir", "")});
  if (!r->Table(t, error)) return false;
  for (const auto& [name, o] : s.items())
    if (!AddClumpCountTable(name, o, r, error)) return false;
  return true;
}

bool CohesionSection(const ReportInputs& in, HtmlReport* r, std::string* error) {
  const nlohmann::json& c = At(*in.results, "cohesion");
  r->Section("2. Cohesion number");
  r->Paragraph("Convention: " + c.value("convention", "") + ". Coh = " +
               Fmt(At(c, "cohesion_number")) + " (paper 1.6e-3; with R* = R/2 it would be " +
               Fmt(At(c, "cohesion_number_pair_radius")) + "). Γ at the simulation stiffness: " +
               Fmt(At(c, "gamma_sim_J_m2")) + " J/m² (paper 0.046). " + c.value("explanation", "") + ".");
  HtmlTable t{.header = {"input", "value"}};
  for (const auto& [k, v] : At(c, "inputs").items()) t.rows.push_back({k, Fmt(v, "%.4g")});
  return r->Table(t, error);
}

bool CoatingSection(const ReportInputs& in, const KeyFigures& key, HtmlReport* r,
                    std::string* error) {
  const nlohmann::json& g = At(*in.results, "gamma_per_coating");
  r->Section("3. Γ per coating level");
  r->Paragraph("Start: 2γ carried to the simulation stiffness, " + Fmt(At(g, "start_gamma_J_m2")) +
               " J/m²; bracketed search on each level's angle, stopping within noise.");
  HtmlTable t{.header = {"coating [wt%]", "Γ ± σ [J/m²]", "angle measured [deg]",
                         "angle demcal [deg]", "provenance", "termination"}};
  for (const nlohmann::json& l : At(g, "levels")) {
    t.rows.push_back({Fmt(At(l, "wt_pct")), PlusMinus(At(l, "value"), At(l, "sigma")),
                      PlusMinus(At(l, "measured"), At(l, "uncertainty"), "%.1f"),
                      PlusMinus(At(l, "simulated"), At(l, "sem"), "%.1f"), l.value("provenance", ""),
                      TerminationText(l)});
    t.synthetic_rows.push_back(l.value("synthetic", false));
  }
  if (!r->Table(t, error)) return false;
  SeeFigure(key.angle, "plots these angles against the coating level", r);
  return true;
}

bool CurveSection(const ReportInputs& in, const KeyFigures& key, HtmlReport* r) {
  const nlohmann::json& c = At(*in.results, "gamma_curve");
  const bool synthetic = c.value("synthetic", false);
  r->Section("4. Γ(w) curve", synthetic);
  if (!c.value("fitted", false)) {
    r->Paragraph("Not fitted: " + c.value("why", std::string("?")));
  } else {
    r->Paragraph("Form " + At(c, "form").get<std::string>() + ", coefficients " + At(c, "coefficients").dump() +
                 ", covariance " + At(c, "covariance").dump() + ", χ²/dof " + Fmt(At(c, "chi2_per_dof")) +
                 ". Γ(" + Fmt(At(c, "coated_wt_pct")) + " wt%) = " +
                 PlusMinus(At(c, "gamma_at_coated_J_m2"), At(c, "gamma_at_coated_sigma_J_m2")) + " J/m².",
                 synthetic);
    if (synthetic)
      r->Paragraph("The comparison with the paper's 0.250 J/m² at 2.5 wt% is circular: the 2.5 wt% "
                   "angle was made by demcal at a Γ(w) through 0.250 J/m² (the synthetic recipe), so "
                   "agreement there tests demcal's repeatability, not the paper.", true);
  }
  SeeFigure(key.gamma_curve, "plots Γ per level with this curve and its 1σ band", r);
  return true;
}

bool PairsSection(const ReportInputs& in, HtmlReport* r, std::string* error) {
  const nlohmann::json& p = At(*in.results, "dissimilar_pairs");
  const bool synthetic = p.value("synthetic", false);
  r->Section("5. Dissimilar pairs", synthetic);
  r->Paragraph("From " + p.value("from", std::string("?")) + ": Γ/2 carried to the pair at constant "
               "Cohesion number. Radius convention: " + p.value("radius_convention", "") + ".");
  HtmlTable t{.header = {"pair", "R*_pair [m]", "factor", "Γ ± σ [J/m²]"}};
  for (const nlohmann::json& q : At(p, "pairs")) {
    t.rows.push_back({At(q, "materials")[0].get<std::string>() + "–" + At(q, "materials")[1].get<std::string>(),
                      Fmt(At(q, "pair_reduced_radius_m")), Fmt(At(q, "factor")),
                      PlusMinus(At(q, "gamma_J_m2"), At(q, "sigma_J_m2"))});
    t.synthetic_rows.push_back(synthetic);
  }
  return r->Table(t, error);
}

}  // namespace

bool SegregationSection(const ReportInputs& in, int bars_figure, HtmlReport* r,
                        std::string* error);
bool TailSections(const ReportInputs& in, HtmlReport* r, std::string* error);

bool WriteReproduceReport(const ReportInputs& in, std::string* error) {
  HtmlReport r("demcal reproduce " + in.workflow->name);
  const RowNotes notes = NumberRowNotes(*in.rows);
  KeyFigures key;
  if (!VerdictSection(in, notes, &r, &key, error) || !SummarySection(in, notes, &r, error) ||
      !SpeciesSection(in, &r, error) || !CohesionSection(in, &r, error) ||
      !CoatingSection(in, key, &r, error) || !CurveSection(in, key, &r) ||
      !PairsSection(in, &r, error) || !SegregationSection(in, key.bars, &r, error) ||
      !TailSections(in, &r, error))
    return false;
  return r.WriteFile(in.out_dir + "/report.html", error) &&
         r.WriteMarkdown(in.out_dir + "/report.md", "figures", error);
}

}  // namespace demcal::workflow
