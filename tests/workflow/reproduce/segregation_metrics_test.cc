// The reproduce workflow's segregation rows: per-run indices taken from a segregation
// experiment's typed result, summarised over replicates, with the random-mixture floor quoted
// beside S_n.
#include "workflow/reproduce/segregation_metrics.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace demcal::workflow;
using nlohmann::json;
namespace objectives = demcal::objectives;

namespace {
// A one-run segregation result, EP only: its indices and the floor of S_n (3D).
SegregationResult Result(double s_n, double floor) {
  SegregationResult r;
  objectives::SegregationRun& run = r.runs.emplace_back();
  run.funnel_emptied = true;  // with a settled heap and its analysis: "ok"
  run.analysis.emplace();
  run.wall_time_s = 1.0;
  run.particles = 10;
  auto one = [](double v) { return objectives::Summarise({v}); };
  SegregationSpeciesResult ep;
  ep.species = "EP";
  ep.indices = {{"s_n_3d", one(s_n)}, {"cov_3d", one(0.5)}, {"outflow_mass_fraction", one(0.02)}};
  ep.floors = {{"s_n_3d_floor", FloorEstimate{floor, 0.9 * floor, 1.2 * floor, 1}}};
  r.species = {ep};
  return r;
}
json Run(double s_n, double floor) { return ExtractSegregationMetrics(Result(s_n, floor)); }
}  // namespace

TEST_CASE("segregation rows carry the replicates' mean and sem and the noise floor", "[unit]") {
  std::vector<json> runs;
  for (double s_n : {1.0, 2.0, 3.0}) runs.push_back(Run(s_n, 1.5));
  CHECK(runs[0]["status"] == "ok");
  CHECK(runs[0]["EP.cov_r_3d"].is_null());  // an index the run does not have: no value
  CHECK(runs[0]["EP.s_n_3d_floor"].get<double>() == Approx(1.5));
  const json uncoated = SummariseSegregationRuns(runs);
  CHECK(uncoated["EP.s_n_3d"]["mean"].get<double>() == Approx(2.0));
  CHECK(uncoated["EP.s_n_3d"]["sem"].get<double>() == Approx(1.0 / std::sqrt(3.0)));
  const json values = SegregationSummaryValues({{"uncoated", uncoated}}, "EP");
  const std::string note = values["s_n_EP_3d_uncoated"]["note"].get<std::string>();
  CHECK(note.find("random-mixture floor 1.5") != std::string::npos);
  // Fig. 16's level: EP's share of what left the funnel.
  CHECK(values["ep_outflow_fraction"]["mean"].get<double>() == Approx(0.02));
  // A scenario that did not run gives no value, and says so.
  CHECK(values["s_n_EP_3d_coated"]["mean"].is_null());
  CHECK(values["s_n_EP_3d_coated"]["note"].get<std::string>().find("no value") != std::string::npos);
}

TEST_CASE("a discharge time from a feed-limited funnel is reported but not compared", "[unit]") {
  auto run = [](double discharge_s, bool feed_limited) {
    SegregationResult r = Result(1.0, 1.5);
    r.runs[0].funnel_feed_limited = feed_limited;
    r.runs[0].funnel_regime = feed_limited ? "feed_limited" : "orifice_limited";
    r.runs[0].funnel_mass_flow_kg_s = feed_limited ? 0.02 : 0.014;
    r.runs[0].feed_duration_s = 1.54;
    r.discharge_time_s = objectives::Summarise({discharge_s});
    return ExtractSegregationMetrics(r);
  };
  const json limited = SummariseSegregationRuns({run(1.60, true), run(1.58, true)});
  const json holding = SummariseSegregationRuns({run(2.30, false), run(2.20, false)});
  const json values = SegregationSummaryValues({{"uncoated", limited}, {"coated", holding}}, "EP");
  const json& u = values["discharge_time_uncoated_s"];
  CHECK(u["mean"].get<double>() == Approx(1.59));
  CHECK(u["comparable"] == false);
  CHECK(u["note"].get<std::string>().find("feed-limited funnel in 100 % of the runs") == 0);
  CHECK(u["note"].get<std::string>().find("1.54 s") != std::string::npos);
  // An orifice-limited funnel's time is compared, and the row says what it rests on.
  const json& c = values["discharge_time_coated_s"];
  CHECK_FALSE(c.contains("comparable"));
  CHECK(c["note"].get<std::string>().find("orifice-limited funnel in 100 % of the runs "
                                          "(steady outflow 0.014 kg/s)") == 0);
}

TEST_CASE("a coarse heap's mixture angle says it is no like-for-like comparison", "[unit]") {
  auto scenario = [](double size_scale) {
    std::vector<json> runs;
    for (double angle : {48.0, 48.4}) {
      SegregationResult r = Result(1.0, 1.5);
      r.mixture_angle_deg = objectives::Summarise({angle});
      json m = ExtractSegregationMetrics(r);
      if (size_scale > 0) m["size_scale"] = size_scale;  // as the reproduce stage records it
      runs.push_back(m);
    }
    return SummariseSegregationRuns(runs);
  };
  auto note = [&](double size_scale) {
    const json values = SegregationSummaryValues({{"uncoated", scenario(size_scale)}}, "EP");
    CHECK(values["mixture_angle_uncoated_deg"]["mean"].get<double>() == Approx(48.2));
    CHECK_FALSE(values["mixture_angle_uncoated_deg"].contains("comparable"));  // still compared
    return values["mixture_angle_uncoated_deg"]["note"].get<std::string>();
  };
  for (double coarse : {4.0, 5.0}) {
    const std::string text = note(coarse);
    CHECK(text.find("not like for like with the paper's measured angle") == 0);
    CHECK(text.find(coarse == 4.0 ? "size ×4 " : "size ×5 ") != std::string::npos);
    CHECK(text.find("34.6 ± 0.9° frictionless") != std::string::npos);
    CHECK(text.find("docs/experiments/segregation_angle.md") != std::string::npos);
  }
  CHECK(note(3.0).empty());  // the side walls' share was not separated at ×3
  CHECK(note(0).empty());    // runs that did not record their size scale
}
