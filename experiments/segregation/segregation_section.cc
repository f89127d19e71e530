#include "experiments/segregation/segregation_section.h"

#include "experiments/common/experiment_sections.h"
#include "files/json_fields.h"
#include "files/scene_json_sections.h"

namespace demcal::workflow {

namespace {

using nlohmann::json;
using objectives::SegregationSettings;

// "funnel": false (pour from the feeder), true (defaults) or an object of dimensions.
void ParseFunnel(const json& value, objectives::FunnelSettings* funnel, JsonStatus* status) {
  if (value.is_boolean()) {
    funnel->enabled = value.get<bool>();
    return;
  }
  JsonFields f(value, "segregation.funnel",
               {"orifice_diameter_m", "effective_orifice_diameter_m", "beverloo_k",
                "top_diameter_m", "height_m"},
               status);
  funnel->enabled = true;
  f.Number("orifice_diameter_m", &funnel->orifice_diameter_m, kOptional, Range::Open(0, 10, "m"));
  // The orifice that follows the fidelity (funnel_geometry.h) excludes a fixed one: a file
  // naming both would leave the reader guessing which the run used.
  if (value.contains("effective_orifice_diameter_m") && value.contains("orifice_diameter_m"))
    f.Fail("effective_orifice_diameter_m",
           "excludes orifice_diameter_m: give the fixed orifice or the rule, not both");
  f.Number("effective_orifice_diameter_m", &funnel->effective_orifice_diameter_m, kOptional,
           Range::Open(0, 10, "m"));
  // k ≥ 3 would put the open width of a just-not-jamming orifice (D = 3 d) at or below zero.
  f.Number("beverloo_k", &funnel->beverloo_k, kOptional, Range{0, 3, false, true, ""});
  f.Number("top_diameter_m", &funnel->top_diameter_m, kOptional, Range::Open(0, 10, "m"));
  f.Number("height_m", &funnel->height_m, kOptional, Range::Open(0, 10, "m"));
}

void ParseBins(const json& value, objectives::HeapBinOptions* bins, JsonStatus* status) {
  JsonFields f(value, "segregation.bins", {"row_bins", "rectangular", "layers"}, status);
  if (const json* rows = f.Array("row_bins", kOptional)) {
    if (rows->empty()) f.Fail("row_bins", "must list at least one row");
    bins->row_bins.clear();
    for (size_t k = 0; k < rows->size() && status->ok(); ++k) {
      const json& n = (*rows)[k];
      if (!n.is_number_integer() || n.get<int64_t>() < 1 || n.get<int64_t>() > 1000)
        status->Fail("field '" + IndexPath(f.PathOf("row_bins"), k) +
                     "' must be an integer in [1, 1000], got " + n.dump());
      else
        bins->row_bins.push_back(n.get<int>());
    }
  }
  f.Bool("rectangular", &bins->rectangular, kOptional);
  int64_t layers = bins->layers;
  f.Integer("layers", &layers, kOptional, Range::Closed(1, 1000));
  bins->layers = static_cast<int>(layers);
}

void ParseIndex(const json& value, objectives::SegregationSettings* s, JsonStatus* status) {
  JsonFields f(value, "segregation.segregation_index",
               {"repetitions", "draw", "packing_fraction", "floor_shuffles", "floor_band"}, status);
  objectives::SegregationOptions* options = &s->segregation;
  int64_t repetitions = options->random.repetitions;
  f.Integer("repetitions", &repetitions, kOptional, Range::Closed(2, 1000000));
  options->random.repetitions = static_cast<int>(repetitions);
  std::string draw = "normal";
  f.String("draw", &draw, kOptional, {"normal", "binomial"});
  options->random.draw =
      draw == "binomial" ? objectives::RandomDraw::kBinomial : objectives::RandomDraw::kNormal;
  f.Number("packing_fraction", &options->packing_fraction, kOptional, Range::LeftOpen(0, 1));
  int64_t shuffles = s->floor.shuffles;
  f.Integer("floor_shuffles", &shuffles, kOptional, Range::Closed(20, 100000));
  s->floor.shuffles = static_cast<int>(shuffles);
  f.Number("floor_band", &s->floor.band, kOptional, Range::Open(0, 1));
}

void ParseTracking(const json& value, const core::Scene& model,
                   objectives::TrackingSettings* tracking, JsonStatus* status) {
  JsonFields f(value, "segregation.tracking",
               {"granules", "species", "sample_interval_s", "start_fraction"}, status);
  int64_t granules = tracking->granules;
  f.Integer("granules", &granules, kOptional, Range::Closed(0, 10000));
  tracking->granules = static_cast<int>(granules);
  if (f.Has("species"))
    tracking->species =
        internal::ReadNameReference(f, "species", "species", internal::SpeciesNames(model), status);
  f.Number("sample_interval_s", &tracking->sample_interval_s, kOptional,
           Range::LeftOpen(0, 1, "s"));
  f.Number("start_fraction", &tracking->start_fraction, kOptional, {0, 1, false, true});
}

void ParseFields(JsonFields& f, const core::Scene& model, SegregationSettings* s,
                 JsonStatus* status) {
  if (const json* feed = f.Object("feed", kRequired))
    ParseFeed(*feed, "segregation.feed", model, &s->feed, status);
  f.Number("width_m", &s->width_m, kOptional, Range::LeftOpen(0, 10, "m"));
  f.Number("depth_m", &s->depth_m, kOptional, Range::LeftOpen(0, 10, "m"));
  f.Number("pour_height_m", &s->pour_height_m, kOptional, Range::LeftOpen(0, 10, "m"));
  f.Number("feed_width_m", &s->feed_width_m, kOptional, Range::LeftOpen(0, 10, "m"));
  if (const json* funnel = f.Value("funnel", kOptional)) ParseFunnel(*funnel, &s->funnel, status);
  s->wall_material = ReadMaterial(f, "wall_material", model, status);
  if (f.Has("funnel_material"))
    s->funnel_material = ReadMaterial(f, "funnel_material", model, status);
  f.Bool("glued_base", &s->glued_base, kOptional);
  if (const json* settle = f.Object("settle", kOptional))
    ParseSettle(*settle, "segregation.settle", &s->settle, status);
  if (const json* bins = f.Object("bins", kOptional)) ParseBins(*bins, &s->bins, status);
  if (const json* index = f.Object("segregation_index", kOptional)) ParseIndex(*index, s, status);
  if (const json* tracking = f.Object("tracking", kOptional))
    ParseTracking(*tracking, model, &s->tracking, status);
  f.Number("max_wall_time_s", &s->max_wall_time_s, kOptional, Range::Closed(0, 1e7, "s"));
}

}  // namespace

bool ParseSegregationSection(const json& section, const std::string& source,
                             const core::Scene& model, SegregationSettings* settings,
                             std::string* error) {
  JsonStatus status;
  SegregationSettings s;
  JsonFields f(
      section, "segregation",
      {"feed", "width_m", "depth_m", "pour_height_m", "feed_width_m", "funnel", "wall_material",
       "funnel_material", "glued_base", "settle", "bins", "segregation_index", "tracking", "max_wall_time_s"},
      &status);
  ParseFields(f, model, &s, &status);
  return FinishSection(status, source, model, s, settings, error);
}

}  // namespace demcal::workflow
