// Rolling-resistance models on a single sphere, against the analytic checks of docs/physics.md §2
// ("Analytic rolling checks"):
//  * EPSD / EPSD2 (Ai et al. 2011 type C): the rolling torque is capped at μ_r R F_n, so a
//    sphere on an incline of angle θ rests iff tan θ ≤ μ_r. Above it, it rolls with
//    a = (5/7) g (sin θ − μ_r cos θ)  (m a = m g sin θ − F_t, I α = R F_t − μ_r R F_n, a = R α).
//  * CDT (EDEM standard rolling friction): a constant resisting torque μ_r R m g on a sphere
//    rolling without slip on a flat gives a = −(5/7) μ_r g and a stopping distance
//    s = 7 v0² / (10 μ_r g).
// The incline is modelled by tilting gravity; the wall is the plane z = 0.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.005;
const Material kMaterial{"glass", 1e8, 0.25, 2500};

// One sphere resting on the floor z = 0 under gravity g (g_z < 0), starting at the static Hertz
// overlap for the normal load so it does not bounce. The domain spans x in [−0.02, x_max].
Scene SphereOnFloor(const std::string& rolling, double mu_r, const Vec3& gravity,
                    const Vec3& velocity, const Vec3& omega, double x_max) {
  Scene s;
  s.materials = {kMaterial};
  s.species = {{"sphere", 0, {}}};
  s.species[0].size.diameter_m = 2 * kRadius;
  PairParameters pp;
  pp.sliding_friction = 0.5;
  pp.rolling_friction = mu_r;
  pp.restitution = 0.5;
  s.pair_parameters = {pp};
  s.rolling.name = rolling;
  s.gravity_m_s2 = gravity;
  s.walls = {PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 0, {}}};
  const double mass =
      kMaterial.density_kg_m3 * 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  const double e_star =
      kMaterial.youngs_modulus_Pa / (2 * (1 - kMaterial.poisson_ratio * kMaterial.poisson_ratio));
  const double overlap =
      std::pow(mass * -gravity.z / (4.0 / 3.0 * e_star * std::sqrt(kRadius)), 2.0 / 3.0);
  s.particles = {{0, {0, 0, kRadius - overlap}, velocity, omega, 2 * kRadius}};
  s.domain_min_m = {-0.02, -0.02, -0.02};
  s.domain_max_m = {x_max, 0.02, 0.02};
  s.time.timestep_s = 1e-5;
  return s;
}

void InitializeOrFail(Simulation& sim) {
  std::string err;
  const bool ok = sim.Initialize(&err);
  INFO(err);
  REQUIRE(ok);
}

void RunOrFail(Simulation& sim, double duration_s) {
  const RunSummary r = sim.Run(duration_s);
  INFO(r.BriefReport());
  REQUIRE(r.ok());
}

}  // namespace

TEST_CASE("EPSD rolling resistance holds a sphere on an incline iff tan(theta) <= mu_r",
          "[physics]") {
  // docs/physics.md §2.2 and "Analytic rolling checks": static iff tan θ ≤ μ_r.
  const double mu_r = 0.1;
  for (const char* model : {"epsd", "epsd2"}) {
    for (const double ratio : {0.9, 1.1}) {
      DYNAMIC_SECTION(model << ", tan(theta) = " << ratio << " mu_r") {
        const double theta = std::atan(ratio * mu_r);
        const Vec3 gravity{kG * std::sin(theta), 0, -kG * std::cos(theta)};
        Simulation sim(SphereOnFloor(model, mu_r, gravity, {}, {}, 0.1), {.threads = 1});
        InitializeOrFail(sim);
        RunOrFail(sim, 0.5);  // settling
        const double x1 = sim.particles().position_m[0].x;
        const double v1 = sim.particles().velocity_m_s[0].x;
        RunOrFail(sim, 0.5);
        const double x2 = sim.particles().position_m[0].x;
        const double v2 = sim.particles().velocity_m_s[0].x;
        const double t = 0.5;
        INFO("x(0.5 s) = " << x1 << " m, x(1 s) = " << x2 << " m, v = " << v1 << ", " << v2
                           << " m/s");
        if (ratio < 1) {
          // At rest: only the elastic rolling-spring deflection (micrometres), then no motion.
          CHECK(std::abs(x1) < 0.01 * kRadius);
          CHECK(std::abs(x2 - x1) < 1e-4 * kRadius);
          CHECK(std::abs(v2) < 1e-5);
        } else {
          // Rolling away with the fully mobilised torque μ_r R F_n.
          const double a = 5.0 / 7.0 * kG * (std::sin(theta) - mu_r * std::cos(theta));
          INFO("acceleration " << (v2 - v1) / t << " m/s² vs (5/7) g (sin θ − μ_r cos θ) = " << a);
          CHECK(x2 - x1 > 0.1 * kRadius);
          CHECK((v2 - v1) / t == Approx(a).epsilon(0.03));
        }
      }
    }
  }
}

TEST_CASE("An adhesive sphere's rolling limit: the transmitted load (net) or the JKR repulsive part",
          "[physics]") {
  // Rolling-slot load of a JKR contact (rolling_model.h, JkrRollingLoad). On an incline the
  // contact transmits N = m g cos θ whatever Γ is (the adhesion is internal to the contact), so
  // with "net" the EPSD limit μ_r R N gives the non-adhesive law: at tan θ = 1.5 μ_r the sphere
  // rolls with a = (5/7) g (sin θ − μ_r cos θ). With "repulsive" the limit multiplies the Hertz
  // part 4E*a³/(3R*) ≈ N + 4F_c (F_c = 3πΓR* ≈ 1.8 m g here, at zero load the Hertz part is
  // 4F_c), more than 1.5 N, so the same sphere is held.
  const double mu_r = 0.1, theta = std::atan(1.5 * mu_r);
  const Vec3 gravity{kG * std::sin(theta), 0, -kG * std::cos(theta)};
  for (const char* load : {"net", "repulsive"}) {
    DYNAMIC_SECTION("jkr_rolling_load " << load) {
      Scene scene = SphereOnFloor("epsd2", mu_r, gravity, {}, {}, 0.2);
      scene.pair_parameters[0].interfacial_energy_J_m2 = 0.5;
      scene.rolling.jkr_rolling_load = load;
      Simulation sim(scene, {.threads = 1});
      InitializeOrFail(sim);
      RunOrFail(sim, 0.3);
      const double x1 = sim.particles().position_m[0].x, v1 = sim.particles().velocity_m_s[0].x;
      RunOrFail(sim, 0.3);
      const double x2 = sim.particles().position_m[0].x, v2 = sim.particles().velocity_m_s[0].x;
      INFO("x = " << x1 << ", " << x2 << " m; v = " << v1 << ", " << v2 << " m/s");
      if (std::string(load) == "net") {
        const double a = 5.0 / 7.0 * kG * (std::sin(theta) - mu_r * std::cos(theta));
        CHECK((v2 - v1) / 0.3 == Approx(a).epsilon(0.03));
      } else {
        CHECK(std::abs(x2 - x1) < 1e-4 * kRadius);
        CHECK(std::abs(v2) < 1e-5);
      }
    }
  }
}

TEST_CASE("CDT rolling friction stops a rolling sphere after 7 v0^2 / (10 mu_r g)", "[physics]") {
  // docs/physics.md §2.1 (EDEM standard rolling friction, constant torque) and "Analytic rolling
  // checks": a = −(5/7) μ_r g, s = 7 v0² / (10 μ_r g) for a sphere rolling without slip. On a
  // wall LIGGGHTS' law (cdt_relative: R* = R, the wall does not spin) is the same torque.
  const char* law = GENERATE("cdt", "cdt_relative");
  INFO("rolling law " << law);
  const double mu_r = 0.2, v0 = 0.5;
  const double s_expected = 7 * v0 * v0 / (10 * mu_r * kG);  // 0.0892 m
  const double t_stop = v0 / (5.0 / 7.0 * mu_r * kG);        // 0.357 s
  Simulation sim(SphereOnFloor(law, mu_r, {0, 0, -kG}, {v0, 0, 0}, {0, v0 / kRadius, 0}, 0.2),
                 {.threads = 1});
  InitializeOrFail(sim);
  RunOrFail(sim, 0.5 * t_stop);
  const double v_mid = sim.particles().velocity_m_s[0].x;
  RunOrFail(sim, t_stop);  // until 1.5 t_stop: the sphere must have stopped
  const Particles& p = sim.particles();
  INFO("v(t_stop/2) = " << v_mid << " m/s vs " << 0.5 * v0);
  INFO("distance " << p.position_m[0].x << " m vs 7 v0²/(10 μ_r g) = " << s_expected << " m");
  INFO("final v = " << p.velocity_m_s[0].x << " m/s, ω = " << p.angular_velocity_rad_s[0].y);
  CHECK(v_mid == Approx(0.5 * v0).epsilon(0.03));
  CHECK(p.position_m[0].x == Approx(s_expected).epsilon(0.03));
  CHECK(std::abs(p.velocity_m_s[0].x) < 1e-3 * v0);
}
