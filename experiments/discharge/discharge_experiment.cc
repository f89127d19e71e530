#include "experiments/discharge/discharge_experiment.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "objectives/common/experiment_scene.h"
#include "experiments/discharge/hopper_fill.h"

namespace demcal::objectives {

namespace {

// Room around the test before a particle counts as lost.
constexpr double kMargin = 0.02;
// A gate waiting for the settle criterion opens "never" until the run knows when (finite, so the
// wall's displacement stays 0 rather than NaN).
constexpr double kLateS = 1e8;

double Gravity(const core::Scene& model) {
  return std::sqrt(Dot(model.gravity_m_s2, model.gravity_m_s2));
}

// Half width of the square catch bin: room for the top of the hopper and for the heap of
// discharged grains around the axis.
double CatchHalfWidth(const DischargeSettings& s) { return 0.75 * s.hopper.top_diameter_m; }

// The gate moves down at a speed the grains falling after it cannot reach within the catch
// depth (they would need 2v²/g), and stops below the catch floor.
double GateTravel(const core::Scene& model, const DischargeSettings& s) {
  return s.catch_depth_m + 2 * FeedMaxDiameter(model, s.feed);
}
double GateSpeed(const core::Scene& model, const DischargeSettings& s) {
  return std::sqrt(Gravity(model) * GateTravel(model, s));
}

core::Wall Gate(const core::Scene& model, const DischargeSettings& s, double t0_s) {
  core::Wall gate(core::PlaneWall{"gate", {0, 0, 0}, {0, 0, 1}, s.wall_material, {}});
  const double v = GateSpeed(model, s);
  gate.velocity_m_s = {0, 0, -v};
  gate.motion_start_s = t0_s;
  gate.motion_end_s = t0_s + GateTravel(model, s) / v;
  return gate;
}

void AddHopper(const DischargeSettings& s, core::Scene* scene) {
  const HopperGeometry& h = s.hopper;
  scene->walls.emplace_back("hopper.cone", s.wall_material,
                            core::ConeFrustumSurface{.height0_m = 0,
                                                     .radius0_m = 0.5 * h.orifice_diameter_m,
                                                     .height1_m = h.ConeHeightM(),
                                                     .radius1_m = 0.5 * h.top_diameter_m});
  if (h.cylinder_height_m > 0)
    scene->walls.emplace_back("hopper.cylinder", s.wall_material,
                              core::CylinderSurface{.radius_m = 0.5 * h.top_diameter_m,
                                                    .axial_min_m = h.ConeHeightM(),
                                                    .axial_max_m = h.TopM()});
}

void AddFeed(const core::Scene& model, const DischargeSettings& s, uint64_t seed,
             core::Scene* scene) {
  if (s.fill == DischargeSettings::Fill::kPour)
    scene->factories.push_back(MakeFeedFactory(model, s.feed, FeedRegion(model, s)));
  else
    scene->particles = PlacedFill(model, s, seed);
}

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

double HopperGeometry::ConeHeightM() const {
  const double half_angle = cone_half_angle_deg * std::numbers::pi / 180;
  return 0.5 * (top_diameter_m - orifice_diameter_m) / std::tan(half_angle);
}

double HopperGeometry::TopM() const { return ConeHeightM() + cylinder_height_m; }

bool DischargeSettings::IsValid(const core::Scene& model, std::string* error) const {
  if (!feed.IsValid(model, "discharge.feed", error)) return false;
  const double d = FeedMaxDiameter(model, feed);
  const HopperGeometry& h = hopper;
  std::ostringstream os;
  if (!(h.orifice_diameter_m > 3 * d))
    os << "discharge.hopper.orifice_diameter_m = " << h.orifice_diameter_m
       << " must exceed 3 largest particle diameters (" << 3 * d << " m at this fidelity)";
  else if (!(h.top_diameter_m > h.orifice_diameter_m + 2 * d))
    os << "discharge.hopper.top_diameter_m = " << h.top_diameter_m
       << " must exceed orifice_diameter_m + 2 largest particle diameters ("
       << h.orifice_diameter_m + 2 * d << " m)";
  else if (!(h.cone_half_angle_deg > 0 && h.cone_half_angle_deg <= 89))
    os << "discharge.hopper.cone_half_angle_deg = " << h.cone_half_angle_deg
       << " is outside the allowed range (0, 89]";
  else if (!(catch_depth_m > 4 * d))
    os << "discharge.catch_depth_m = " << catch_depth_m
       << " must exceed 4 largest particle diameters (" << 4 * d << " m at this fidelity)";
  else if (wall_material < 0 || wall_material >= static_cast<int>(model.materials.size()))
    os << "discharge.wall_material names no defined material";
  else if (gate_open_s > 0 && fill == Fill::kPour && !(gate_open_s > feed.EndS()))
    os << "discharge.gate_open_s = " << gate_open_s << " s must come after the pour ends at "
       << feed.EndS() << " s";
  else if (!(sample_interval_s > 0 && stall_s >= 2 * sample_interval_s))
    os << "discharge.stall_s = " << stall_s << " s must span at least 2 samples of "
       << "sample_interval_s = " << sample_interval_s << " s";
  else if (!(max_discharge_s > stall_s))
    os << "discharge.max_discharge_s = " << max_discharge_s << " s must exceed stall_s";
  else if (!(analysis.flow_window_high <= analysis.discharge_fraction))
    os << "discharge.analysis.flow_window_high = " << analysis.flow_window_high
       << " must not exceed discharge_fraction = " << analysis.discharge_fraction
       << " (the run stops there)";
  else if (FitsInHopper(model, *this, &os))
    FitsInCatchBin(model, *this, &os);
  if (!os.str().empty()) return Fail(error, os.str());
  return analysis.IsValid(error);
}

core::Scene BuildDischargeScene(const core::Scene& model, const DischargeSettings& s,
                                uint64_t seed) {
  core::Scene scene = EmptyExperimentScene(model, seed, s.max_wall_time_s);
  AddHopper(s, &scene);
  scene.walls.push_back(Gate(model, s, s.gate_open_s > 0 ? s.gate_open_s : kLateS));
  const double half = CatchHalfWidth(s);
  const core::BoxFaces bin = core::BoxInnerFaces(
      "catch", {-half, -half, -s.catch_depth_m}, {half, half, 1}, s.wall_material, true);
  for (const core::PlaneWall& face : bin) scene.walls.push_back(face);
  AddFeed(model, s, seed, &scene);
  const double top = FillTopM(model, s);
  scene.domain_min_m = {-half - kMargin, -half - kMargin, -s.catch_depth_m - kMargin};
  scene.domain_max_m = {half + kMargin, half + kMargin, top + kMargin};
  const double gate_s = s.gate_open_s > 0 ? s.gate_open_s : s.settle.max_time_s;
  scene.time.duration_s = gate_s + s.max_discharge_s;  // the longest run
  return scene;
}

void OpenGateAt(double t0_s, core::Scene* scene) {
  for (core::Wall& wall : scene->walls)
    if (wall.name == "gate") {
      const double travel = wall.motion_end_s - wall.motion_start_s;
      wall.motion_start_s = t0_s;
      wall.motion_end_s = t0_s + travel;
    }
}

}  // namespace demcal::objectives
