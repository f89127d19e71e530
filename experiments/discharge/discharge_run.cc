// RunDischarge (discharge_experiment.h): fill with the gate closed, open it, record the outflow
// until the hopper is empty, jammed or out of time, then analyse the record.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <thread>

#include "experiments/discharge/discharge_experiment.h"
#include "experiments/discharge/hopper_fill.h"
#include "experiments/discharge/outflow_recorder.h"

namespace demcal::objectives {

namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

core::Simulation::Observer Every(const core::Simulation& sim, double interval_s,
                                 std::function<bool(const core::Simulation&)> callback) {
  return {std::max<int64_t>(1, std::llround(interval_s / sim.timestep_s())), std::move(callback)};
}

// Runs the fill phase until the gate opens (at its set time or once settled); false with the
// run's status when it fails.
bool Fill(core::Simulation& sim, const core::Scene& model, const DischargeSettings& s,
          const RunHooks& hooks, DischargeRun* out) {
  if (s.gate_open_s > 0) {
    const core::RunSummary run =
        sim.Run(s.gate_open_s, Every(sim, s.settle.check_interval_s, [&](const core::Simulation& x) {
          if (hooks.progress) hooks.progress(x.time_s(), s.gate_open_s);
          if (hooks.on_check) hooks.on_check(x);
          return true;
        }));
    out->status = run.ok() ? "ok" : core::TerminationName(run.termination);
    out->message = run.message;
    return run.ok();
  }
  SettleCriteria criteria = s.settle;
  criteria.feed_end_s = FillEndS(model, s);
  const SettleResult settled = RunUntilSettled(sim, criteria, [&](double t, double end) {
    if (hooks.progress) hooks.progress(t, end);
    if (hooks.on_check) hooks.on_check(sim);
  });
  out->status = settled.status;
  out->message = settled.message;
  return settled.ok();
}

std::string TemporaryCheckpointPath(uint64_t seed) {
  static std::atomic<uint64_t> counter{0};
  std::ostringstream name;
  name << "demcal_discharge_" << std::hash<std::thread::id>{}(std::this_thread::get_id()) << "_"
       << seed << "_" << counter++ << ".ckpt";
  return (std::filesystem::temp_directory_path() / name.str()).string();
}

// A simulation of `scene` with the gate opening now, continuing the settled state of `filled`
// (the gate's motion is part of the scene, fixed at initialisation: hand over by checkpoint).
std::unique_ptr<core::Simulation> OpenGateNow(core::Scene scene, const core::Simulation& filled,
                                              double budget_s, int threads, std::string* error) {
  OpenGateAt(filled.time_s(), &scene);
  if (budget_s > 0) scene.max_wall_time_s = std::max(1.0, budget_s);
  const std::string path = TemporaryCheckpointPath(scene.seed);
  auto sim = std::make_unique<core::Simulation>(scene, core::Simulation::Options{.threads = threads});
  const bool ok = filled.SaveCheckpoint(path, error) && sim->Initialize(error) &&
                  sim->LoadCheckpoint(path, error, {"wall motion"});
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  return ok ? std::move(sim) : nullptr;
}

struct DischargeEnd {
  bool empty = false;
  bool done = false;  // empty, or discharge_fraction of the fill is out
  bool stalled = false;
  core::RunSummary run;
};

// Samples the outflow from t0 on until discharge_fraction of the fill is out (nothing after it
// enters the metrics), the outflow stalls or time is up.
DischargeEnd Discharge(core::Simulation& sim, const DischargeSettings& s, double fill_kg,
                       const RunHooks& hooks, OutflowRecorder* recorder) {
  DischargeEnd end;
  const double t0 = sim.time_s();
  const double done_kg = s.analysis.discharge_fraction * fill_kg;
  double last_out_kg = recorder->total_out_kg(), last_change_s = t0;
  auto sample = [&](const core::Simulation& x) {
    recorder->Sample(x);
    if (hooks.on_check) hooks.on_check(x);
    const double t = x.time_s(), out_kg = recorder->total_out_kg();
    if (out_kg > last_out_kg) last_out_kg = out_kg, last_change_s = t;
    if (hooks.progress) {
      const double rate = t > t0 ? out_kg / (t - t0) : 0;  // rough ETA from the mean flow
      hooks.progress(t, rate > 0 ? t + recorder->remaining_kg() / rate : t0 + s.max_discharge_s);
    }
    end.empty = recorder->remaining_count() == 0;
    end.done = end.empty || out_kg >= done_kg;
    end.stalled = t - last_change_s > s.stall_s;
    return !end.done && !end.stalled;
  };
  end.run = sim.Run(s.max_discharge_s, Every(sim, s.sample_interval_s, sample));
  if (!end.done && !end.stalled && end.run.ok()) recorder->Sample(sim);
  return end;
}

// The run's status from how the discharge ended and what stayed in the hopper.
void Classify(const DischargeEnd& end, const OutflowRecorder& recorder,
              const DischargeSettings& s, DischargeRun* out) {
  std::ostringstream os;
  const double left = recorder.remaining_kg();
  const bool nearly_empty = left <= (1 - s.analysis.discharge_fraction) * out->fill_mass_kg;
  if (!end.run.ok()) {
    out->status = core::TerminationName(end.run.termination);
    out->message = end.run.message;
    return;
  }
  if (end.done || nearly_empty) {
    out->status = "ok";
    if (!end.empty)
      os << recorder.remaining_count() << " grains (" << left << " kg) still in the hopper when "
         << (end.done ? "discharge_fraction of the fill was out" : "the outflow stalled");
  } else {
    out->status = end.stalled ? "jammed" : "not_empty";
    os << (end.stalled ? "no outflow for " : "time up after ")
       << (end.stalled ? s.stall_s : s.max_discharge_s) << " s with " << left << " kg ("
       << 100 * left / out->fill_mass_kg << "% of the fill) left in the hopper";
  }
  out->message = os.str();
}

}  // namespace

DischargeRun RunDischarge(const core::Scene& model, const DischargeSettings& settings,
                          uint64_t seed, const RunHooks& hooks) {
  const Clock::time_point start = Clock::now();
  DischargeRun out;
  out.seed = seed;
  const core::Scene scene = BuildDischargeScene(model, settings, seed);
  auto sim = std::make_unique<core::Simulation>(scene, core::Simulation::Options{.threads = std::max(1, hooks.threads)});
  std::string error;
  if (!sim->Initialize(&error)) {
    out.status = "invalid_scene";
    out.message = error;
    return out;
  }
  bool ok = Fill(*sim, model, settings, hooks, &out);
  if (ok && settings.gate_open_s <= 0) {
    sim = OpenGateNow(scene, *sim, settings.max_wall_time_s - SecondsSince(start),
                      std::max(1, hooks.threads), &error);
    if (!sim) out.status = "invalid_scene", out.message = error;
    ok = sim != nullptr;
  }
  if (ok) {
    out.gate_open_s = sim->time_s();
    OutflowRecorder recorder(model.species.size(), 0.0);
    recorder.Sample(*sim);
    out.fill_mass_kg = recorder.remaining_kg();
    out.bulk_density_kg_m3 = HopperBulkDensity(sim->particles(), settings.hopper,
                                               FeedMaxDiameter(model, settings.feed));
    const DischargeEnd end = Discharge(*sim, settings, out.fill_mass_kg, hooks, &recorder);
    Classify(end, recorder, settings, &out);
    out.samples = recorder.samples();
    DischargeOptions options = settings.analysis;
    options.expected_total_mass_kg = out.fill_mass_kg;
    out.metrics = AnalyseDischarge(out.samples, out.gate_open_s, options);
    if (out.status == "ok" && !out.metrics.ok) out.message = out.metrics.message;
  }
  if (sim) {
    if (hooks.on_finish) hooks.on_finish(*sim);
    out.particles = static_cast<int64_t>(sim->particles().Size());
  }
  out.wall_time_s = SecondsSince(start);
  return out;
}

}  // namespace demcal::objectives
