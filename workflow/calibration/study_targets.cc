// Targets of a study: an observable of an experiment under a condition, with its measurement
// from a row of the tidy table (value, uncertainty, provenance), or a stated uncertainty where
// the table gives none.
#include <sstream>

#include "calibrate/observable_registry.h"
#include "files/measurement_table.h"
#include "workflow/calibration/study_sections.h"

namespace demcal::workflow {
namespace {

std::string ObservableChoice(JsonFields& f, const std::string& key, std::string* out) {
  f.String(key, out, kRequired, calibrate::ObservableNames());
  return *out;
}

// A stated uncertainty at least the observable's floor, so that every χ² term stays finite
// (limits::kMinUncertaintyFraction, objectives/common/input_limits.h).
void CheckUncertainty(JsonFields& f, const std::string& key, const std::string& observable,
                      double u) {
  const calibrate::ObservableInfo* info = calibrate::FindObservable(observable);
  if (!f.ok() || !info || (u >= info->MinUncertainty() && u <= info->max - info->min)) return;
  std::ostringstream os;
  os << "= " << u << " " << info->unit << " is outside the allowed range "
     << info->UncertaintyRangeText() << " for " << observable;
  f.Fail(key, os.str());
}

// Fills value, uncertainty, provenance, repeats and source of *t from the table row.
struct MeasureKeys {
  const char* table;
  const char* uncertainty;
};

void Measure(const std::string& table_path, const std::string& material, double assumed,
             MeasureKeys keys, JsonFields& f, StudyTarget* t) {
  MeasurementTable table;
  std::string error;
  if (!LoadMeasurementTable(table_path, &table, &error)) return f.Fail(keys.table, error);
  const MeasurementRow* row = table.Find(t->target.observable, material, t->condition, &error);
  if (!row) return f.Fail(keys.table, error);
  t->target.value = row->value;
  t->target.uncertainty = row->HasUncertainty() ? row->uncertainty : assumed;
  if (!row->HasUncertainty() && assumed > 0)
    CheckUncertainty(f, keys.uncertainty, t->target.observable, assumed);
  t->target.source = table.path + " line " + std::to_string(row->line) + " (" + row->source + ")";
  t->provenance = row->provenance;
  t->repeats = row->repeats;
  t->condition = row->conditions;  // the row's whole condition: what this target stands for
  if (!row->HasUncertainty() && !(assumed > 0))
    f.Fail(keys.uncertainty, "required: the table row (" + table.path + " line " +
                              std::to_string(row->line) + ") gives no uncertainty, so the study "
                              "must state the one it assumes (> 0, the observable's unit)");
}

}  // namespace

void ParseStudyTarget(const nlohmann::json& j, const std::string& path, const std::string& table,
                      StudyFile* study, JsonStatus* status) {
  JsonFields f(j, path, {"name", "experiment_file", "observable", "measurement"}, status);
  StudyTarget t;
  std::string experiment;
  f.String("experiment_file", &experiment, kRequired);
  ObservableChoice(f, "observable", &t.target.observable);
  const nlohmann::json* m = f.Object("measurement", kRequired);
  if (!f.ok()) return;
  t.experiment = StudyExperimentIndex(experiment, f.PathOf("experiment_file"), study, status);
  JsonFields mf(*m, f.PathOf("measurement"),
                {"table", "material", "conditions", "uncertainty", "uncertainty_note"}, status);
  std::string material, own_table;
  double assumed = 0;
  mf.String("table", &own_table, table.empty() ? kRequired : kOptional);
  mf.String("material", &material, kRequired);
  mf.Number("uncertainty", &assumed, kOptional, Range::LeftOpen(0, 1e6));
  mf.String("uncertainty_note", &t.note, kOptional);
  if (const nlohmann::json* c = mf.Object("conditions", kOptional); c && mf.ok())
    ParseCondition(*c, mf.PathOf("conditions"), &t.condition, status);
  if (!mf.ok()) return;
  Measure(own_table.empty() ? table : ResolveStudyPath(study->source, own_table), material, assumed,
          {"table", "uncertainty"}, mf, &t);
  if (!mf.ok()) return;
  t.target.name = t.target.observable + " " + material +
                  (t.condition.empty() ? "" : " (" + calibrate::DescribeCondition(t.condition) + ")");
  f.String("name", &t.target.name, kOptional);
  for (const StudyTarget& other : study->targets)
    if (other.target.name == t.target.name) return f.Fail("name", "'" + t.target.name + "' is used twice");
  study->targets.push_back(t);
}

void ParseStudyCandidateTarget(const nlohmann::json& j, const std::string& path, StudyFile* study,
                               JsonStatus* status) {
  JsonFields f(j, path, {"name", "experiment_file", "observable", "condition", "uncertainty"}, status);
  StudyCandidateTarget t;
  std::string experiment;
  f.String("experiment_file", &experiment, kRequired);
  ObservableChoice(f, "observable", &t.observable);
  f.Number("uncertainty", &t.uncertainty, kRequired, Range::LeftOpen(0, 1e6));
  CheckUncertainty(f, "uncertainty", t.observable, t.uncertainty);
  if (const nlohmann::json* c = f.Object("condition", kOptional); c && f.ok())
    ParseCondition(*c, f.PathOf("condition"), &t.condition, status);
  if (!f.ok()) return;
  t.experiment = StudyExperimentIndex(experiment, f.PathOf("experiment_file"), study, status);
  t.name = t.observable + " (" + experiment + ")";
  f.String("name", &t.name, kOptional);
  study->candidate_targets.push_back(t);
}

void ParseLegacyMeasurement(const nlohmann::json& j, const std::string& path, StudyFile* study,
                            JsonStatus* status) {
  JsonFields f(j, path, {"dataset", "material", "coating_PEG_wt_pct", "uncertainty_deg", "uncertainty_note"},
               status);
  StudyTarget t;
  std::string dataset, material;
  double coating = 0, assumed = 0;
  f.String("dataset", &dataset, kRequired);
  f.String("material", &material, kRequired);
  f.Number("coating_PEG_wt_pct", &coating, kOptional, Range::Closed(0, 100, "wt%"));
  f.Number("uncertainty_deg", &assumed, kOptional, Range::LeftOpen(0, 90, "deg"));
  f.String("uncertainty_note", &t.note, kOptional);
  if (!f.ok()) return;
  std::ostringstream w;
  w << coating;
  t.target.observable = "angle_deg";
  t.condition = {{"coating_PEG_wt_pct", w.str()}};
  Measure(ResolveStudyPath(study->source, dataset), material, assumed, {"dataset", "uncertainty_deg"},
          f, &t);
  if (!f.ok()) return;
  t.target.name = "angle_deg " + material;
  study->targets.push_back(t);
}

}  // namespace demcal::workflow
