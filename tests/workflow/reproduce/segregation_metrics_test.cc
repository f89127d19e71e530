// The reproduce workflow's segregation rows: per-run indices pulled from an experiment's
// result.json, summarised over replicates, with the random-mixture floor quoted beside S_n.
#include "workflow/reproduce/segregation_metrics.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace demcal::workflow;
using nlohmann::json;

namespace {
// A one-run segregation result.json of the experiment's shape, EP only.
json Run(double s_n, double floor) {
  return {{"runs", {{{"status", "ok"}, {"wall_time_s", 1.0}, {"particles", 10}}}},
          {"species",
           {{{"species", "EP"},
             {"s_n_3d", {{"mean", s_n}}},
             {"s_n_3d_floor", {{"mean", floor}, {"low", 0.9 * floor}, {"high", 1.2 * floor}}},
             {"cov_3d", {{"mean", 0.5}}},
             {"outflow_mass_fraction", {{"mean", 0.02}}}}}}};
}
}  // namespace

TEST_CASE("segregation rows carry the replicates' mean and sem and the noise floor", "[unit]") {
  std::vector<json> runs;
  for (double s_n : {1.0, 2.0, 3.0}) runs.push_back(ExtractSegregationMetrics(Run(s_n, 1.5)));
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
    json r = Run(1.0, 1.5);
    r["runs"][0]["funnel_feed_limited"] = feed_limited;
    r["runs"][0]["feed_duration_s"] = 1.54;
    r["discharge_time_s"] = {{"mean", discharge_s}};
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
  CHECK_FALSE(values["discharge_time_coated_s"].contains("comparable"));
}
