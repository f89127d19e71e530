#include "experiments/aor/aor_section.h"

#include "experiments/common/experiment_sections.h"
#include "files/json_fields.h"

namespace demcal::workflow {

namespace {

using nlohmann::json;

void ParseAngleOptions(const json& value, objectives::ReposeAngleOptions* a, JsonStatus* status) {
  JsonFields f(value, "aor.angle",
               {"window_low", "window_high", "cell_m", "sectors", "min_flank_points", "method"},
               status);
  std::string method = "fit";
  f.String("method", &method, kOptional, {"fit", "two_point", "fit_else_two_point"});
  using Method = objectives::ReposeAngleOptions::Method;
  a->method = method == "two_point"            ? Method::kTwoPoint
              : method == "fit_else_two_point" ? Method::kFitElseTwoPoint
                                               : Method::kFit;
  f.Number("window_low", &a->window_low, kOptional, Range::Closed(0, 1));
  f.Number("window_high", &a->window_high, kOptional, Range::Closed(0, 1));
  f.Number("cell_m", &a->cell_m, kOptional, Range::Closed(0, 1, "m"));
  int64_t sectors = a->sectors, points = a->min_flank_points;
  f.Integer("sectors", &sectors, kOptional, Range::Closed(1, 360));
  f.Integer("min_flank_points", &points, kOptional, Range::Closed(3, 1000));
  if (status->ok() && !(a->window_low < a->window_high))
    f.Fail("window_high", "= " + FormatNumber(a->window_high) + " must exceed window_low = " +
                              FormatNumber(a->window_low));
  a->sectors = static_cast<int>(sectors);
  a->min_flank_points = static_cast<int>(points);
}

}  // namespace

bool ParseAorSection(const json& section, const std::string& source, const core::Scene& model,
                     objectives::AorSettings* settings, std::string* error) {
  JsonStatus status;
  objectives::AorSettings s;
  JsonFields f(section, "aor",
               {"heap", "feed", "width_m", "depth_m", "pour_height_m", "feed_width_m",
                "wall_material", "glued_base", "settle", "angle", "max_wall_time_s"},
               &status);
  std::string heap = "slot";
  f.String("heap", &heap, kOptional, {"slot", "conical"});
  s.heap = heap == "conical" ? objectives::AorSettings::Heap::kConical
                             : objectives::AorSettings::Heap::kSlot;
  if (const json* feed = f.Object("feed", kRequired)) ParseFeed(*feed, "aor.feed", model, &s.feed, &status);
  f.Number("width_m", &s.width_m, kOptional, Range::LeftOpen(0, 10, "m"));
  f.Number("depth_m", &s.depth_m, kOptional, Range::LeftOpen(0, 10, "m"));
  f.Number("pour_height_m", &s.pour_height_m, kOptional, Range::LeftOpen(0, 10, "m"));
  f.Number("feed_width_m", &s.feed_width_m, kOptional, Range::LeftOpen(0, 10, "m"));
  s.wall_material = ReadMaterial(f, "wall_material", model, &status);
  f.Bool("glued_base", &s.glued_base, kOptional);
  if (const json* settle = f.Object("settle", kOptional)) ParseSettle(*settle, "aor.settle", &s.settle, &status);
  if (const json* angle = f.Object("angle", kOptional)) ParseAngleOptions(*angle, &s.angle, &status);
  f.Number("max_wall_time_s", &s.max_wall_time_s, kOptional, Range::Closed(0, 1e7, "s"));
  return FinishSection(status, source, model, s, settings, error);
}

}  // namespace demcal::workflow
