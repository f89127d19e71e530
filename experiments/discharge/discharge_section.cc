#include "experiments/discharge/discharge_section.h"

#include "experiments/common/experiment_sections.h"
#include "files/json_fields.h"

namespace demcal::workflow {

namespace {

using nlohmann::json;
using objectives::DischargeSettings;

void ParseHopper(const json& value, objectives::HopperGeometry* h, JsonStatus* status) {
  JsonFields f(value, "discharge.hopper",
               {"top_diameter_m", "orifice_diameter_m", "cone_half_angle_deg",
                "cylinder_height_m"},
               status);
  f.Number("top_diameter_m", &h->top_diameter_m, kRequired, Range::LeftOpen(0, 10, "m"));
  f.Number("orifice_diameter_m", &h->orifice_diameter_m, kRequired, Range::LeftOpen(0, 10, "m"));
  f.Number("cone_half_angle_deg", &h->cone_half_angle_deg, kOptional,
           Range::LeftOpen(0, 89, "deg"));
  f.Number("cylinder_height_m", &h->cylinder_height_m, kOptional, Range::Closed(0, 10, "m"));
}

void ParseAnalysis(const json& value, objectives::DischargeOptions* a, JsonStatus* status) {
  JsonFields f(value, "discharge.analysis",
               {"discharge_fraction", "flow_window_low", "flow_window_high", "composition_bins",
                "composition_bin_s"},
               status);
  f.Number("discharge_fraction", &a->discharge_fraction, kOptional, Range::LeftOpen(0, 1));
  f.Number("flow_window_low", &a->flow_window_low, kOptional, Range::Closed(0, 1));
  f.Number("flow_window_high", &a->flow_window_high, kOptional, Range::Closed(0, 1));
  int64_t bins = a->composition_bins;
  f.Integer("composition_bins", &bins, kOptional, Range::Closed(1, 10000));
  a->composition_bins = static_cast<int>(bins);
  f.Number("composition_bin_s", &a->composition_bin_s, kOptional, Range::Closed(0, 1e4, "s"));
  if (status->ok() && !(a->flow_window_low < a->flow_window_high))
    f.Fail("flow_window_high", "must exceed flow_window_low = " +
                                   FormatNumber(a->flow_window_low));
}

// A placed fill has no pour rate: the feed may leave mass_rate_kg_s out (a nominal one is set).
json FeedWithRate(const json& feed, DischargeSettings::Fill fill) {
  json copy = feed;
  if (fill == DischargeSettings::Fill::kPlace && copy.is_object() &&
      !copy.contains("mass_rate_kg_s"))
    copy["mass_rate_kg_s"] = 1.0;
  return copy;
}

}  // namespace

bool ParseDischargeSection(const json& section, const std::string& source,
                           const core::Scene& model, DischargeSettings* settings,
                           std::string* error) {
  JsonStatus status;
  DischargeSettings s;
  JsonFields f(section, "discharge",
               {"fill", "feed", "hopper", "feed_diameter_m", "catch_depth_m", "wall_material",
                "gate_open_s", "settle", "sample_interval_s", "stall_s", "max_discharge_s",
                "analysis", "max_wall_time_s"},
               &status);
  std::string fill = "pour";
  f.String("fill", &fill, kOptional, {"pour", "place"});
  s.fill = fill == "place" ? DischargeSettings::Fill::kPlace : DischargeSettings::Fill::kPour;
  if (const json* feed = f.Object("feed", kRequired)) {
    const json with_rate = FeedWithRate(*feed, s.fill);
    ParseFeed(with_rate, "discharge.feed", model, &s.feed, &status);
  }
  if (const json* hopper = f.Object("hopper", kRequired)) ParseHopper(*hopper, &s.hopper, &status);
  f.Number("feed_diameter_m", &s.feed_diameter_m, kOptional, Range::Closed(0, 10, "m"));
  f.Number("catch_depth_m", &s.catch_depth_m, kOptional, Range::LeftOpen(0, 10, "m"));
  s.wall_material = ReadMaterial(f, "wall_material", model, &status);
  f.Number("gate_open_s", &s.gate_open_s, kOptional, Range::Closed(0, 1e4, "s"));
  if (const json* settle = f.Object("settle", kOptional))
    ParseSettle(*settle, "discharge.settle", &s.settle, &status);
  f.Number("sample_interval_s", &s.sample_interval_s, kOptional, Range::LeftOpen(0, 10, "s"));
  f.Number("stall_s", &s.stall_s, kOptional, Range::LeftOpen(0, 1e3, "s"));
  f.Number("max_discharge_s", &s.max_discharge_s, kOptional, Range::LeftOpen(0, 1e4, "s"));
  if (const json* analysis = f.Object("analysis", kOptional))
    ParseAnalysis(*analysis, &s.analysis, &status);
  f.Number("max_wall_time_s", &s.max_wall_time_s, kOptional, Range::Closed(0, 1e7, "s"));
  return FinishSection(status, source, model, s, settings, error);
}

}  // namespace demcal::workflow
