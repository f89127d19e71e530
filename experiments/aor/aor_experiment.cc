#include "experiments/aor/aor_experiment.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/math/random.h"
#include "core/simulation/simulation.h"
#include "objectives/common/experiment_scene.h"
#include "objectives/common/glued_base.h"

namespace demcal::objectives {

namespace {

using core::Vec3;

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

// Room above the feed region and around the test before a particle counts as lost.
constexpr double kMargin = 0.02;

GluedBaseSpec BaseSpec(const core::Scene& model, const AorSettings& s, uint64_t seed) {
  GluedBaseSpec base = GluedBaseOfFeed(model, s.feed, seed);
  if (s.heap == AorSettings::Heap::kSlot) {
    base.min_m = {0, 0, 0};
    base.max_m = {s.width_m, s.depth_m, 0};
  } else {
    const double r = 0.5 * s.width_m;
    base.min_m = {-r, -r, 0};
    base.max_m = {r, r, 0};
    base.disc_radius_m = r;
  }
  return base;
}

double FeedRegionHeight(const core::Scene& model, const AorSettings& s) {
  return std::max(6 * FeedMaxDiameter(model, s.feed), 0.01);
}

void AddSlotGeometry(const AorSettings& s, double top_m, core::Scene* scene) {
  const core::BoxFaces box =
      core::BoxInnerFaces("box", {0, 0, 0}, {s.width_m, s.depth_m, top_m}, s.wall_material, true);
  for (const core::PlaneWall& face : box) scene->walls.push_back(face);
  scene->domain_min_m = {-kMargin, -kMargin, -kMargin};
  scene->domain_max_m = {s.width_m + kMargin, s.depth_m + kMargin, top_m + kMargin};
}

void AddConicalGeometry(const AorSettings& s, double top_m, core::Scene* scene) {
  const double catch_r = 0.8 * s.width_m;
  scene->walls.push_back(core::PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, s.wall_material, {}});
  core::Wall rim("catch", s.wall_material,
                 core::CylinderSurface{.axis_point_m = {0, 0, 0}, .radius_m = catch_r});
  scene->walls.push_back(rim);
  scene->domain_min_m = {-catch_r - kMargin, -catch_r - kMargin, -kMargin};
  scene->domain_max_m = {catch_r + kMargin, catch_r + kMargin, top_m + kMargin};
}

core::InsertionRegion FeedRegion(const core::Scene& model, const AorSettings& s) {
  const double z0 = s.pour_height_m, z1 = z0 + FeedRegionHeight(model, s);
  if (s.heap == AorSettings::Heap::kConical)
    return core::InsertionRegion::Cylinder({0, 0, 0}, 0.5 * s.feed_width_m, z0, z1);
  const double x0 = 0.5 * (s.width_m - s.feed_width_m);
  return core::InsertionRegion::Box({x0, 0, z0}, {x0 + s.feed_width_m, s.depth_m, z1});
}

}  // namespace

bool AorSettings::IsValid(const core::Scene& model, std::string* error) const {
  if (!feed.IsValid(model, "aor.feed", error)) return false;
  const double d = FeedMaxDiameter(model, feed);
  std::ostringstream os;
  if (!(width_m > 10 * d))
    os << "aor.width_m = " << width_m << " must exceed 10 largest particle diameters (" << 10 * d
       << " m at this fidelity)";
  else if (heap == Heap::kSlot && !(depth_m > 3 * d))
    os << "aor.depth_m = " << depth_m << " must exceed 3 largest particle diameters (" << 3 * d
       << " m at this fidelity)";
  else if (!(feed_width_m > 3 * d && feed_width_m <= width_m))
    os << "aor.feed_width_m = " << feed_width_m << " is outside the allowed range (" << 3 * d
       << ", width_m = " << width_m << "] m at this fidelity";
  else if (!(pour_height_m > 2 * d && pour_height_m < 10))
    os << "aor.pour_height_m = " << pour_height_m << " is outside the allowed range (" << 2 * d
       << ", 10) m";
  else if (wall_material < 0 || wall_material >= static_cast<int>(model.materials.size()))
    os << "aor.wall_material names no defined material";
  else if (!(settle.max_time_s > feed.EndS()))
    os << "aor.max_time_s = " << settle.max_time_s << " s must exceed the pour time "
       << feed.EndS() << " s";
  if (!os.str().empty()) return Fail(error, os.str());
  return angle.IsValid(error);
}

core::Scene BuildAorScene(const core::Scene& model, const AorSettings& s, uint64_t seed,
                          int64_t* fixed_count) {
  core::Scene scene = EmptyExperimentScene(model, seed, s.max_wall_time_s);
  const double top = s.pour_height_m + FeedRegionHeight(model, s) + kMargin;
  if (s.heap == AorSettings::Heap::kSlot)
    AddSlotGeometry(s, top, &scene);
  else
    AddConicalGeometry(s, top, &scene);
  if (s.glued_base) {
    GluedBaseSpec base = BaseSpec(model, s, seed);
    UseSphereSpeciesForBase(&scene, &base);
    scene.particles = GluedBase(base);
  }
  *fixed_count = static_cast<int64_t>(scene.particles.size());
  scene.factories.push_back(MakeFeedFactory(model, s.feed, FeedRegion(model, s)));
  scene.time.duration_s = s.settle.max_time_s;
  return scene;
}

AorRun RunAor(const core::Scene& model, const AorSettings& settings, uint64_t seed,
              const RunHooks& hooks) {
  const auto start = std::chrono::steady_clock::now();
  AorRun out;
  out.seed = seed;
  int64_t fixed = 0;
  core::Scene scene = BuildAorScene(model, settings, seed, &fixed);
  core::Simulation sim(scene, {.threads = std::max(1, hooks.threads)});
  if (!InitializeSettledRun(sim, &out.settle)) return out;
  SettleCriteria criteria = settings.settle;
  criteria.feed_end_s = settings.feed.EndS();
  out.settle = RunUntilSettled(sim, criteria, [&](double t, double end) {
    if (hooks.progress) hooks.progress(t, end);
    if (hooks.on_check) hooks.on_check(sim);
  });
  if (hooks.on_finish) hooks.on_finish(sim);
  out.heap = Select(TakeSnapshot(sim), [&](const Grain& g) { return g.id >= fixed; });
  const bool slot = settings.heap == AorSettings::Heap::kSlot;
  const double r = 0.5 * settings.width_m;
  if (!slot) out.heap = Crop(out.heap, {-r, -r, -1}, {r, r, 1e9});
  out.particles = static_cast<int64_t>(out.heap.grains.size());
  out.angle_options = settings.angle;
  out.angle_options.base_z_m =
      settings.glued_base ? GluedBaseTop(BaseSpec(model, settings, seed)) : 0.0;
  if (out.settle.ok())
    out.angle = slot ? MeasureSlotHeapAngle(out.heap, out.angle_options)
                     : MeasureConicalHeapAngle(out.heap, {0, 0, 0}, out.angle_options);
  out.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace demcal::objectives
