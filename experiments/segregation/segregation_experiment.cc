#include "experiments/segregation/segregation_experiment.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "core/math/random.h"
#include "core/math/seed_streams.h"
#include "core/simulation/simulation.h"
#include "objectives/common/experiment_scene.h"
#include "experiments/discharge/funnel_clock.h"
#include "experiments/discharge/outflow_recorder.h"
#include "objectives/common/glued_base.h"
#include "experiments/segregation/granule_recorder.h"

namespace demcal::objectives {

namespace {

// Room around the test before a particle counts as lost.
constexpr double kMargin = 0.02;
// Gap between the funnel top and the feed region.
constexpr double kFeedGap = 0.005;
// Tracked granules are sampled this far below the orifice: grains that fell this far move
// faster than SurfaceOptions::max_surface_speed_m_s, so the stream is not taken for the surface.
constexpr double kTrackBelowOrifice = 0.02;

GluedBaseSpec BaseSpec(const core::Scene& model, const SegregationSettings& s, uint64_t seed) {
  GluedBaseSpec base = GluedBaseOfFeed(model, s.feed, seed);
  base.min_m = {0, 0, 0};
  base.max_m = {s.width_m, s.depth_m, 0};
  return base;
}

// Six grain lengths, so that elongated clumps find room as spheres do.
double FeedRegionHeight(const core::Scene& model, const SegregationSettings& s) {
  return std::max(6 * FeedMaxEnclosingDiameter(model, s.feed), 0.01);
}

double FeedRegionBottom(const SegregationSettings& s) {
  return s.funnel.enabled ? s.pour_height_m + s.funnel.height_m + kFeedGap : s.pour_height_m;
}

core::InsertionRegion FeedRegion(const core::Scene& model, const SegregationSettings& s) {
  const double z0 = FeedRegionBottom(s), x0 = 0.5 * (s.width_m - s.feed_width_m);
  return core::InsertionRegion::Box(
      {x0, 0, z0}, {x0 + s.feed_width_m, s.depth_m, z0 + FeedRegionHeight(model, s)});
}

double OrificeM(const core::Scene& model, const SegregationSettings& s) {
  return s.funnel.OrificeDiameterM(FeedMaxMeanCaliperDiameter(model, s.feed));
}

core::Wall Funnel(const core::Scene& model, const SegregationSettings& s) {
  const FunnelSettings& f = s.funnel;
  return core::Wall("funnel", s.FunnelMaterial(),
                    core::ConeFrustumSurface{.axis_point_m = {0.5 * s.width_m, 0.5 * s.depth_m, 0},
                                             .height0_m = s.pour_height_m,
                                             .radius0_m = 0.5 * OrificeM(model, s),
                                             .height1_m = s.pour_height_m + f.height_m,
                                             .radius1_m = 0.5 * f.top_diameter_m});
}

std::string CheckGeometry(const core::Scene& model, const SegregationSettings& s) {
  const double d = FeedMaxDiameter(model, s.feed);
  const FunnelSettings& f = s.funnel;
  const double orifice = OrificeM(model, s);
  std::ostringstream os;
  if (!(s.width_m > 10 * d))
    os << "segregation.width_m = " << s.width_m << " must exceed 10 largest particle diameters ("
       << 10 * d << " m at this fidelity)";
  else if (!(s.depth_m > 3 * d))
    os << "segregation.depth_m = " << s.depth_m << " must exceed 3 largest particle diameters ("
       << 3 * d << " m at this fidelity)";
  else if (!(s.pour_height_m > 2 * d && s.pour_height_m < 10))
    os << "segregation.pour_height_m = " << s.pour_height_m << " is outside the allowed range ("
       << 2 * d << ", 10) m";
  else if (f.enabled && f.ScalesWithFidelity() && !(orifice > 3 * d))
    os << "segregation.funnel.effective_orifice_diameter_m = " << f.effective_orifice_diameter_m
       << " with beverloo_k = " << f.beverloo_k << " gives an orifice of " << orifice
       << " m at this fidelity (largest grain " << d << " m), which must exceed 3 largest particle "
       << "diameters (" << 3 * d << " m): the funnel would jam; effective_orifice_diameter_m must "
       << "exceed " << 3 * d - f.beverloo_k * FeedMaxMeanCaliperDiameter(model, s.feed) << " m";
  else if (f.enabled && !(std::min(orifice, s.depth_m) > 3 * d))
    os << "segregation.funnel.orifice_diameter_m = " << orifice << " (cut to depth_m = "
       << s.depth_m << ") must exceed 3 largest particle diameters (" << 3 * d
       << " m at this fidelity): the funnel would jam";
  else if (f.enabled && !(f.top_diameter_m > orifice && f.top_diameter_m <= s.width_m))
    os << "segregation.funnel.top_diameter_m = " << f.top_diameter_m
       << " is outside the allowed range (orifice diameter " << orifice
       << " m at this fidelity, width_m = " << s.width_m << "] m";
  else if (f.enabled && !(f.height_m > 0 && f.height_m < 10))
    os << "segregation.funnel.height_m = " << f.height_m
       << " is outside the allowed range (0, 10) m";
  else if (!(s.feed_width_m > 3 * d &&
             s.feed_width_m <= (f.enabled ? f.top_diameter_m : s.width_m)))
    os << "segregation.feed_width_m = " << s.feed_width_m << " is outside the allowed range ("
       << 3 * d << ", " << (f.enabled ? "funnel.top_diameter_m = " : "width_m = ")
       << (f.enabled ? f.top_diameter_m : s.width_m) << "] m at this fidelity";
  return os.str();
}

std::string CheckRun(const core::Scene& model, const SegregationSettings& s) {
  const TrackingSettings& t = s.tracking;
  std::ostringstream os;
  if (s.wall_material < 0 || s.wall_material >= static_cast<int>(model.materials.size()))
    os << "segregation.wall_material names no defined material";
  else if (s.FunnelMaterial() >= static_cast<int>(model.materials.size()))
    os << "segregation.funnel_material names no defined material";
  else if (!(s.settle.max_time_s > s.feed.EndS()))
    os << "segregation.settle.max_time_s = " << s.settle.max_time_s
       << " s must exceed the pour time " << s.feed.EndS() << " s";
  else if (t.granules < 0 || t.granules > 10000)
    os << "segregation.tracking.granules = " << t.granules
       << " is outside the allowed range [0, 10000]";
  else if (t.species < -1 || t.species >= static_cast<int>(model.species.size()))
    os << "segregation.tracking.species names no defined species";
  else if (!(t.sample_interval_s > 0 && t.sample_interval_s <= 1))
    os << "segregation.tracking.sample_interval_s = " << t.sample_interval_s
       << " is outside the allowed range (0, 1] s";
  else if (!(t.start_fraction >= 0 && t.start_fraction < 1))
    os << "segregation.tracking.start_fraction = " << t.start_fraction
       << " is outside the allowed range [0, 1)";
  return os.str();
}

HeapBinOptions BinOptions(const SegregationSettings& s) {
  HeapBinOptions bins = s.bins;
  bins.y_min_m = 0;
  bins.y_max_m = s.depth_m;
  return bins;
}

GranuleRecorderOptions RecorderOptions(const core::Scene& model, const SegregationSettings& s) {
  const TrackingSettings& t = s.tracking;
  GranuleRecorderOptions r;
  r.species = s.TrackedSpecies();
  r.count = t.granules;
  r.start_time_s = s.feed.start_s + t.start_fraction * s.feed.DurationS();
  double fraction = 0;
  for (const FeedComponent& c : s.feed.components)
    if (c.species == r.species) fraction += c.mass_fraction;
  r.stride =
      TrackingStride(model, s.feed.mass_kg, fraction, r.species, t.start_fraction, t.granules);
  r.below_z_m = s.pour_height_m - kTrackBelowOrifice;
  r.surface = t.surface;
  return r;
}

TrackedGranule SummariseTrack(const GranuleTrack& track, const Snapshot& heap,
                              const TrackingSettings& t) {
  TrackedGranule out;
  out.track = track;
  out.impact_sample = FirstSpeedDropIndex(track, t.impact);
  if (out.impact_sample) {
    out.impact_time_s = track.samples[*out.impact_sample].time_s;
    for (int k = 0; k <= *out.impact_sample; ++k)
      out.peak_specific_kinetic_J_kg =
          std::max(out.peak_specific_kinetic_J_kg, track.samples[k].SpecificKineticEnergyJPerKg());
  }
  std::string ignored;  // a granule outside the heap simply has no depth
  out.penetration = PenetrationDepth(heap, track.id, t.surface, &ignored);
  return out;
}

void Analyse(const core::Scene& model, const SegregationSettings& s, uint64_t seed,
             SegregationRun* out) {
  SegregationOptions options = s.segregation;
  options.random.seed = core::DeriveSeed(seed, core::kSegregationIndexStream);
  const int species = static_cast<int>(model.species.size());
  out->analysis = AnalyseSegregationHeap(out->heap, BinOptions(s), species, options, std::nullopt,
                                         &out->analysis_message);
  if (out->analysis) {
    SegregationFloorOptions floor = s.floor;
    floor.seed = core::DeriveSeed(seed, core::kSegregationFloorStream);
    out->floor = RandomMixtureFloor(out->analysis->grid, out->heap, out->analysis->indices, floor,
                                    &out->analysis_message);
  }
  out->angle_options = s.angle;
  out->angle_options.base_z_m = s.glued_base ? GluedBaseTop(BaseSpec(model, s, seed)) : 0.0;
  out->angle = MeasureSlotHeapAngle(out->heap, out->angle_options);
}

}  // namespace

int SegregationSettings::TrackedSpecies() const {
  if (tracking.species >= 0 || feed.components.empty()) return tracking.species;
  return std::min_element(feed.components.begin(), feed.components.end(),
                          [](const FeedComponent& a, const FeedComponent& b) {
                            return a.mass_fraction < b.mass_fraction;
                          })
      ->species;
}

bool SegregationSettings::IsValid(const core::Scene& model, std::string* error) const {
  if (!feed.IsValid(model, "segregation.feed", error)) return false;
  std::string problem = CheckGeometry(model, *this);
  if (problem.empty()) problem = CheckRun(model, *this);
  if (!problem.empty()) {
    if (error) *error = problem;
    return false;
  }
  return angle.IsValid(error) && BinOptions(*this).IsValid(error) &&
         segregation.random.IsValid(error) && floor.IsValid(error);
}

std::string SegregationRun::Status() const {
  if (!settle.ok()) return settle.status;
  if (!funnel_emptied) return "funnel_not_empty";
  if (!analysis) return "no_analysis";
  return "ok";
}

core::Scene BuildSegregationScene(const core::Scene& model, const SegregationSettings& s,
                                  uint64_t seed, int64_t* fixed_count) {
  core::Scene scene = EmptyExperimentScene(model, seed, s.max_wall_time_s);
  const double top = FeedRegionBottom(s) + FeedRegionHeight(model, s) + kMargin;
  for (const core::PlaneWall& face :
       core::BoxInnerFaces("box", {0, 0, 0}, {s.width_m, s.depth_m, top}, s.wall_material, true))
    scene.walls.push_back(face);
  if (s.funnel.enabled) scene.walls.push_back(Funnel(model, s));
  scene.domain_min_m = {-kMargin, -kMargin, -kMargin};
  scene.domain_max_m = {s.width_m + kMargin, s.depth_m + kMargin, top + kMargin};
  if (s.glued_base) {  // fixed particles are spheres: a clump feed gets a sphere layer
    GluedBaseSpec base = BaseSpec(model, s, seed);
    UseSphereSpeciesForBase(&scene, &base);
    scene.particles = GluedBase(base);
  }
  *fixed_count = static_cast<int64_t>(scene.particles.size());
  scene.factories.push_back(MakeFeedFactory(model, s.feed, FeedRegion(model, s)));
  scene.time.duration_s = s.settle.max_time_s;
  return scene;
}

namespace {

// Fig. 16: the outflow composition in 20 bins from the first grain out to 99 % of the mass out
// (the bin count of the paper's figure is not given; 20 bins over ~1.5 s are 75 ms each, enough
// grains per bin to read a fraction of the majority species and short enough to see a drift).
void AnalyseOutflow(const OutflowRecorder& outflow, double first_out_s, SegregationRun* out) {
  const DischargeMetrics m = AnalyseDischarge(outflow.samples(), first_out_s, {.composition_bins = 20});
  if (!m.ok || outflow.samples().empty()) return;
  out->outflow = m.composition;
  out->funnel_mass_flow_kg_s = m.mass_flow_kg_s;
  const std::vector<double>& total = outflow.samples().back().cumulative_mass_kg;
  double sum = 0;
  for (double kg : total) sum += kg;
  for (double kg : total) out->outflow_mass_fraction.push_back(sum > 0 ? kg / sum : 0);
}

}  // namespace

SegregationRun RunSegregation(const core::Scene& model, const SegregationSettings& settings,
                              uint64_t seed, const RunHooks& hooks) {
  const auto start = std::chrono::steady_clock::now();
  SegregationRun out;
  out.seed = seed;
  int64_t fixed = 0;
  core::Simulation sim(BuildSegregationScene(model, settings, seed, &fixed), {.threads = std::max(1, hooks.threads)});
  if (!InitializeSettledRun(sim, &out.settle)) return out;
  SettleCriteria criteria = settings.settle;
  criteria.feed_end_s = settings.feed.EndS();
  // A funnel drains for seconds after the feed ends, and until the heap's energy decays only the
  // hard stop bounds the run: a guess of the pour's end made the progress fall back from 79 % to
  // 27 % at that moment on a size x4 clump heap; from the hard stop it only moves forward.
  if (settings.funnel.enabled) criteria.expected_end_s = criteria.max_time_s;
  criteria.check_interval_s =
      std::min(criteria.check_interval_s, settings.tracking.sample_interval_s);
  FunnelClock clock(settings.pour_height_m, criteria.feed_end_s);
  GranuleRecorder recorder(RecorderOptions(model, settings), seed);
  OutflowRecorder outflow(model.species.size(), settings.pour_height_m);
  double feed_inserted_s = -1;  // the first check at which the feed had inserted its mass
  out.settle = RunUntilSettled(sim, criteria, [&](double t, double end) {
    if (hooks.progress) hooks.progress(t, end);
    if (feed_inserted_s < 0 && FeedInserted(sim, settings.feed)) feed_inserted_s = t;
    clock.Observe(sim);
    recorder.Observe(sim);
    if (settings.funnel.enabled) outflow.Sample(sim);
    if (hooks.on_check) hooks.on_check(sim);
  });
  if (hooks.on_finish) hooks.on_finish(sim);
  clock.Observe(sim);
  out.funnel_emptied = clock.emptied();
  out.first_out_s = clock.first_out_s();
  out.empty_s = clock.empty_s();
  out.discharge_time_s = clock.DischargeTimeS();
  // A feed whose factory fell behind (large clumps) pours longer than mass / rate: the funnel's
  // regime compares its discharge with the pour it actually got.
  out.feed_duration_s = FeedTookS(settings.feed, feed_inserted_s, criteria.check_interval_s);
  out.funnel_feed_limited = settings.funnel.enabled && clock.emptied() &&
                            FeedLimited(out.discharge_time_s, out.feed_duration_s,
                                        settings.funnel.height_m, Norm(model.gravity_m_s2));
  if (settings.funnel.enabled)
    out.funnel_regime = FunnelRegime(clock.emptied(), out.discharge_time_s, out.feed_duration_s,
                                     settings.funnel.height_m, Norm(model.gravity_m_s2));
  if (settings.funnel.enabled) out.funnel_orifice_diameter_m = OrificeM(model, settings);
  out.spheres_left_above = clock.spheres_above();
  if (settings.funnel.enabled && clock.started()) AnalyseOutflow(outflow, clock.first_out_s(), &out);
  out.heap = Crop(Select(TakeSnapshot(sim), [&](const Grain& g) { return g.id >= fixed; }),
                  {0, 0, -1}, {settings.width_m, settings.depth_m, settings.pour_height_m});
  out.particles = static_cast<int64_t>(out.heap.grains.size());
  if (out.settle.ok())
    Analyse(model, settings, seed, &out);
  else
    out.analysis_message = "not analysed: the run ended with " + out.settle.status;
  for (const GranuleTrack& track : recorder.tracks())
    out.tracked.push_back(SummariseTrack(track, out.heap, settings.tracking));
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace demcal::objectives
