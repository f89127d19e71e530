#include "workflow/reproduce/shape_search.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/math/number_text.h"
#include "files/json_document.h"
#include "objectives/farm/farm.h"
#include "workflow/reproduce/experiment_edit.h"
#include "workflow/reproduce/stages.h"

namespace demcal::workflow {
namespace {

namespace farm = objectives::farm;

std::string Deg(double v) {
  std::ostringstream os;
  os.precision(3);
  os << v;
  return os.str();
}

// The species' experiment file with the property held at `start` and `count` spheres chained on
// the start aspect ratio's spheroid (the calibration reshapes that chain per candidate). Rank 0
// writes it; every rank passes the Share only once it is there.
bool WriteCountExperiment(const WorkflowSpecies& s, int count, const std::string& dir,
                          const std::string& path, std::string* error) {
  nlohmann::ordered_json e;
  if (!ReadExperimentJson(s.experiment_file, &e, error)) return false;
  SetPairProperty(&e, s.name, s.name, s.property, s.start);
  SetSpeciesClump(&e, s.name, {s.aspect_ratio.start, 1, 1}, count);
  std::string written = "ok";
  if (farm::IsManager()) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) written = "cannot create '" + dir + "': " + ec.message();
    else if (!WriteJsonFile(path, e, &written)) written = "cannot write '" + path + "': " + written;
  }
  farm::Share(&written);
  if (written != "ok") return *error = written, false;
  return true;
}

}  // namespace

ShapeSearchRow ShapeRowOf(const WorkflowSpecies& s, int count, const CalibrationOutcome& o) {
  const AspectRatioSearch& a = s.aspect_ratio;
  ShapeSearchRow row;
  row.count = count;
  row.aspect_max = ConnectedAspectLimit(count, a.min, a.max);
  row.aspect_min = DistinctAspectLimit(count, a.min, row.aspect_max);
  if (count >= 2) {
    row.aspect_ratio = o.value;
    row.aspect_sigma = std::isfinite(o.sigma) ? o.sigma : NAN;
    // The bracket evaluates the bounds exactly: the best candidate equals one or lies inside.
    row.aspect_at_bound = o.value <= row.aspect_min || o.value >= row.aspect_max;
  } else {
    row.aspect_sigma = NAN;  // a sphere: nothing calibrated
  }
  row.angle_deg = o.simulated;
  row.angle_sem_deg = o.sem;
  row.measured_deg = o.measured;
  row.uncertainty_deg = o.uncertainty;
  row.cost = o.uncertainty > 0 ? std::pow((o.simulated - o.measured) / o.uncertainty, 2) : NAN;
  row.within_noise = o.termination == calibrate::Termination::kWithinNoise;
  row.termination = calibrate::TerminationName(o.termination);
  row.message = o.message;
  row.result_dir = o.result_dir;
  if (count >= 2 && o.by_line) {  // the line's crossing (calibration_step.h)
    row.local_fit = true;
    row.within_noise = o.Matched();
    row.message = "aspect ratio " + o.local_crossing.message + "; the search: " + o.message;
  }
  return row;
}

namespace {

// Heaps and wall time of a count's calibration, from its result.json (rank 0 wrote it; every
// rank takes rank 0's copy).
void ReadCost(ShapeSearchRow* row) {
  std::string text;
  if (farm::IsManager()) {
    nlohmann::json r;
    std::string error;
    if (ReadJsonFile(row->result_dir + "/result.json", "calibration result", &r, &error))
      text = r.dump();
  }
  farm::Share(&text);
  if (text.empty()) return;
  const nlohmann::json r = nlohmann::json::parse(text);
  row->heaps = r.value("replicates_run", 0) + r.value("replicates_reused", 0);
  row->wall_time_s = r.value("wall_time_s", 0.0);
}

// A row's shape and fit in words, for the notes.
std::string RowText(const ShapeSearchRow& r) {
  std::string text = std::to_string(r.count) + (r.count == 1 ? " sphere" : " spheres");
  if (r.count >= 2) text += " at aspect ratio " + core::NumberText(r.aspect_ratio);
  return text + " (" + Deg(r.angle_deg) + " ± " + Deg(r.angle_sem_deg) + " deg against " +
         Deg(r.measured_deg) + " ± " + Deg(r.uncertainty_deg) +
         (r.local_fit ? ", by a line through the candidates around the crossing" : "") + ")";
}

std::string Note(const WorkflowSpecies& s, const ShapeSearch& out) {
  std::string note;
  if (out.chosen > 0) {
    note = "chose " + RowText(out.rows.back()) + ", the smallest count whose calibrated shape "
           "matches the measured angle within noise";
    if (out.rows.back().aspect_at_bound)
      note += " (its aspect ratio is a bound of the range searched: a wider range could let a "
              "smaller count match)";
  } else if (const ShapeSearchRow* r = out.Used()) {
    note = "no count matched the measured angle within noise with " + s.property + " held at " +
           core::NumberText(s.start) + " and the aspect ratio in [" +
           core::NumberText(s.aspect_ratio.min) + ", " + core::NumberText(s.aspect_ratio.max) +
           "]; the nearest, " + RowText(*r) + ", is what the later stages run";
  } else {
    note = "no count gave a heap";
  }
  std::string at_bound;
  for (const ShapeSearchRow& r : out.rows)
    if (r.aspect_at_bound && !r.within_noise) at_bound += (at_bound.empty() ? "" : ", ") +
                                                          std::to_string(r.count);
  if (!at_bound.empty())
    note += "; at " + at_bound + " spheres the best aspect ratio sits on its bound and still "
            "misses";
  if (!out.not_run.empty()) {
    std::string counts;
    for (int n : out.not_run) counts += (counts.empty() ? "" : ", ") + std::to_string(n);
    note += "; counts " + counts + " not run (a smaller count matched)";
  }
  return note;
}

}  // namespace

const ShapeSearchRow* ShapeSearch::Used() const {
  for (const ShapeSearchRow& r : rows)
    if (r.count == chosen) return &r;
  return nearest >= 0 ? &rows[nearest] : nullptr;
}

nlohmann::json ShapeSearch::TableJson() const {
  nlohmann::json table = {{"rows", nlohmann::json::array()}, {"note", note}};
  for (const ShapeSearchRow& r : rows) {
    std::string row_note = r.message;
    if (r.count >= 2 && !std::isfinite(r.aspect_sigma))
      row_note = "the aspect ratio's standard error is not determined; " + row_note;
    if (r.aspect_at_bound && !r.within_noise)
      row_note = "best aspect ratio at a bound (lower bound " + core::NumberText(r.aspect_min) +
                 ": the shortest chain whose spheres stand apart, or the workflow's; upper bound " +
                 core::NumberText(r.aspect_max) +
                 ": the longest chain whose spheres touch, or the workflow's), still not within "
                 "noise; " + row_note;
    table["rows"].push_back({{"count", r.count},
                             {"aspect_ratio", r.aspect_ratio},
                             {"aspect_ratio_sigma", NumOrNull(r.aspect_sigma)},
                             {"aspect_at_bound", r.aspect_at_bound},
                             {"aspect_ratio_min", r.aspect_min},
                             {"aspect_ratio_max", r.aspect_max},
                             {"angle_deg", NumOrNull(r.angle_deg)},
                             {"angle_sem_deg", NumOrNull(r.angle_sem_deg)},
                             {"cost", NumOrNull(r.cost)},
                             {"within_noise", r.within_noise},
                             {"local_fit", r.local_fit},
                             {"agrees", r.within_noise},
                             {"termination", r.termination},
                             {"note", row_note},
                             {"heaps", r.heaps},
                             {"wall_time_s", r.wall_time_s}});
  }
  return table;
}

CalibrationStep ShapeStep(const WorkflowFile& w, size_t k, int count,
                          const std::string& experiment_file, const std::string& dir) {
  const WorkflowSpecies& s = w.species[k];
  CalibrationStep step = SpeciesStep(w, k, dir);
  step.dir = dir;
  step.experiment_file = experiment_file;
  step.max_evaluations = 1;  // count 1: the sphere at the held property, one candidate
  if (count >= 2) {
    step.parameter = "aspect_ratio_" + s.name;
    step.property = "aspect_ratio";
    step.max = ConnectedAspectLimit(count, s.aspect_ratio.min, s.aspect_ratio.max);
    step.min = DistinctAspectLimit(count, s.aspect_ratio.min, step.max);
    step.start = std::clamp(s.aspect_ratio.start, step.min, step.max);
    step.max_evaluations = s.aspect_ratio.max_evaluations;
  }
  return step;
}

bool RunShapeSearch(const ReproduceContext& ctx, size_t k, const std::string& dir,
                    ShapeSearch* out, std::string* error) {
  const WorkflowFile& w = *ctx.workflow;
  const WorkflowSpecies& s = w.species[k];
  *out = ShapeSearch{};
  for (int n : s.clump_counts) {
    if (out->chosen > 0) {
      out->not_run.push_back(n);
      continue;
    }
    const std::string count_dir = dir + "/clumps_" + std::to_string(n);
    const std::string experiment = count_dir + "/experiment.json";
    if (!WriteCountExperiment(s, n, count_dir, experiment, error)) return false;
    *ctx.log << "reproduce: " << s.name << ": " << n << (n == 1 ? " sphere" : " spheres")
             << (n >= 2 ? ", aspect ratio calibrated" : "") << ", " << s.property << " held at "
             << s.start << "\n";
    CalibrationOutcome o;
    if (!RunCalibrationStep(ctx, ShapeStep(w, k, n, experiment, count_dir), &o, error))
      return false;
    out->rows.push_back(ShapeRowOf(s, n, o));
    ReadCost(&out->rows.back());
    if (out->rows.back().within_noise) out->chosen = n;
  }
  for (size_t r = 0; r < out->rows.size(); ++r)
    if (std::isfinite(out->rows[r].cost) &&
        (out->nearest < 0 || out->rows[r].cost < out->rows[out->nearest].cost))
      out->nearest = static_cast<int>(r);
  out->note = Note(s, *out);
  return true;
}

}  // namespace demcal::workflow
