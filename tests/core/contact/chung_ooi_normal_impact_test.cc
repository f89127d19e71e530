// Chung & Ooi (2011) Granular Matter 13:643, benchmark tests 1–3 (normal impacts), with the
// inputs and Hertz values of docs/physics.md §4.1. The analytic values are Hertz theory
// (docs/physics.md §1.5): δ_max = (15 m* v² / (16 E* √R*))^{2/5}, F_max = (4/3) E* √R* δ_max^{3/2},
// t_c = 2 (δ_max / v) ∫₀¹ (1 − x^{5/2})^{-1/2} dx = 2.9433 δ_max / v (the integral is
// B(2/5, 1/2) / (5/2), evaluated with std::tgamma).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "core/simulation/simulation.h"

using namespace demcal::core;

namespace {

constexpr double kPi = std::numbers::pi;

double SphereMass(double radius, double density) {
  return density * 4.0 / 3.0 * kPi * radius * radius * radius;
}

// 1/E* = (1 − ν_i²)/E_i + (1 − ν_j²)/E_j (docs/physics.md §1.1).
double EffectiveYoungs(const Material& a, const Material& b) {
  return 1.0 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus_Pa +
                (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus_Pa);
}

struct Hertz {
  double max_overlap_m, max_force_N, contact_time_s;
};

Hertz HertzImpact(double e_star, double r_star, double m_star, double v) {
  const double integral = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9) / 2.5;
  const double d = std::pow(15.0 * m_star * v * v / (16.0 * e_star * std::sqrt(r_star)), 0.4);
  return {d, 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(d, 1.5), 2.0 * integral * d / v};
}

// Base scene: one particle material (index 0) and, optionally, a wall material (index 1).
Scene ImpactScene(const Material& particle, const Material* wall, double diameter,
                  double restitution, double friction) {
  Scene s;
  s.materials = {particle};
  if (wall) s.materials.push_back(*wall);
  s.species = {{"sphere", 0, {}}};
  s.species[0].size.diameter_m = diameter;
  PairParameters pp;
  pp.restitution = restitution;
  pp.sliding_friction = friction;
  pp.rolling_friction = 0;
  s.pair_parameters.assign(s.materials.size() * s.materials.size(), pp);
  s.rolling.name = "none";
  s.gravity_m_s2 = {0, 0, 0};
  return s;
}

void InitializeOrFail(Simulation& sim) {
  std::string err;
  const bool ok = sim.Initialize(&err);
  INFO(err);
  REQUIRE(ok);
}

// What one impact did, sampled every step; contact start/end are interpolated linearly to
// the zero crossing of the overlap.
struct ImpactRecord {
  double max_overlap_m = 0;
  double max_force_N = 0;
  double start_s = -1, end_s = -1;
  double ContactTime() const { return end_s - start_s; }
};

// Runs `sim` step by step until the contact described by `overlap(sim)` has ended.
template <class Overlap>
ImpactRecord RecordImpact(Simulation& sim, double max_duration_s, Overlap overlap) {
  ImpactRecord rec;
  double prev_overlap = overlap(sim), prev_t = sim.time_s();
  Simulation::Observer obs;
  obs.every_steps = 1;
  obs.callback = [&](const Simulation& s) {
    const double d = overlap(s), t = s.time_s();
    if (d > 0) {
      rec.max_overlap_m = std::max(rec.max_overlap_m, d);
      // Gravity is off, so the total force on the particle is its contact force.
      rec.max_force_N = std::max(rec.max_force_N, Norm(s.particles().force_N[0]));
    }
    if (prev_overlap <= 0 && d > 0 && rec.start_s < 0)
      rec.start_s = prev_t + (t - prev_t) * (-prev_overlap) / (d - prev_overlap);
    const bool ended = prev_overlap > 0 && d <= 0 && rec.start_s >= 0;
    if (ended) rec.end_s = prev_t + (t - prev_t) * prev_overlap / (prev_overlap - d);
    prev_overlap = d;
    prev_t = t;
    return !ended;
  };
  const RunSummary r = sim.Run(max_duration_s, obs);
  INFO(r.BriefReport());
  REQUIRE(r.ok());
  return rec;
}

void CheckAgainstHertz(const ImpactRecord& rec, const Hertz& h) {
  INFO("max overlap " << rec.max_overlap_m << " m vs Hertz " << h.max_overlap_m << " m");
  INFO("max force " << rec.max_force_N << " N vs Hertz " << h.max_force_N << " N");
  INFO("contact time " << rec.ContactTime() << " s vs Hertz " << h.contact_time_s << " s");
  REQUIRE(rec.end_s > rec.start_s);
  CHECK(rec.max_overlap_m == Approx(h.max_overlap_m).epsilon(0.01));
  CHECK(rec.max_force_N == Approx(h.max_force_N).epsilon(0.01));
  CHECK(rec.ContactTime() == Approx(h.contact_time_s).epsilon(0.01));
}

}  // namespace

TEST_CASE("Hertz closed form reproduces the Chung & Ooi reference numbers of physics.md",
          "[unit]") {
  // docs/physics.md §4.1 table, tests 1 and 2 (rigid wall: E* = E/(1 − ν²)).
  const double m_glass = SphereMass(0.01, 2800);
  const Hertz glass = HertzImpact(48e9 / (2 * (1 - 0.04)), 0.005, 0.5 * m_glass, 20);
  CHECK(glass.max_overlap_m == Approx(274.1e-6).epsilon(1e-3));
  CHECK(glass.max_force_N == Approx(10.70e3).epsilon(1e-3));
  CHECK(glass.contact_time_s == Approx(40.34e-6).epsilon(1e-3));
  const Hertz al = HertzImpact(70e9 / (1 - 0.09), 0.1, SphereMass(0.1, 2699), 0.2);
  CHECK(al.max_overlap_m == Approx(49.72e-6).epsilon(1e-3));
  CHECK(al.max_force_N == Approx(11.37e3).epsilon(1e-3));
  CHECK(al.contact_time_s == Approx(0.7316e-3).epsilon(1e-3));
}

TEST_CASE("Chung & Ooi test 1: elastic impact of two identical spheres matches Hertz",
          "[physics]") {
  // Chung & Ooi 2011 test 1; inputs and expected values docs/physics.md §4.1: R = 10 mm,
  // v = ±10 m/s, e = 1, μ = 0.35.
  struct Case {
    Material material;
    Hertz reference;  // docs/physics.md §4.1 table
  };
  const Case cases[] = {
      {{"glass", 48e9, 0.20, 2800}, {274.1e-6, 10.70e3, 40.34e-6}},
      {{"limestone", 20e9, 0.25, 2500}, {368.3e-6, 7.108e3, 54.20e-6}},
  };
  for (const Case& c : cases) {
    SECTION(c.material.name) {
      const double r = 0.010, v = 10.0;
      const double m = SphereMass(r, c.material.density_kg_m3);
      const Hertz h = HertzImpact(EffectiveYoungs(c.material, c.material), 0.5 * r, 0.5 * m, 2 * v);
      CHECK(h.max_overlap_m == Approx(c.reference.max_overlap_m).epsilon(1e-3));

      Scene s = ImpactScene(c.material, nullptr, 2 * r, 1.0, 0.35);
      const double gap = 1e-5;
      s.particles = {{0, {-(r + 0.5 * gap), 0, 0}, {v, 0, 0}, {}, 2 * r},
                     {0, {r + 0.5 * gap, 0, 0}, {-v, 0, 0}, {}, 2 * r}};
      s.domain_min_m = {-0.1, -0.1, -0.1};
      s.domain_max_m = {0.1, 0.1, 0.1};
      s.time.timestep_s = h.contact_time_s / 1000;
      Simulation sim(s, {.threads = 1});
      InitializeOrFail(sim);
      const ImpactRecord rec =
          RecordImpact(sim, gap / (2 * v) + 2 * h.contact_time_s, [r](const Simulation& q) {
            const auto& x = q.particles().position_m;
            return 2 * r - Norm(x[0] - x[1]);
          });
      CheckAgainstHertz(rec, h);
    }
  }
}

TEST_CASE("Chung & Ooi test 2: elastic impact of a sphere on a rigid plane matches Hertz",
          "[physics]") {
  // Chung & Ooi 2011 test 2; docs/physics.md §4.1: R = 0.1 m, v = 0.2 m/s, e = 1; the wall is
  // 1000× stiffer (as in Yade's script). The engine is compared with Hertz for the actual E*
  // and, as a second check, with the docs/physics.md rigid-wall values (which differ by < 0.1 %).
  struct Case {
    Material material;
    Hertz rigid_reference;  // docs/physics.md §4.1 table
  };
  const Case cases[] = {
      {{"al_alloy", 70e9, 0.30, 2699}, {49.72e-6, 11.37e3, 0.7316e-3}},
      {{"mg_alloy", 40e9, 0.35, 1800}, {52.12e-6, 7.233e3, 0.7670e-3}},
  };
  for (const Case& c : cases) {
    SECTION(c.material.name) {
      const double r = 0.1, v = 0.2;
      Material wall = c.material;
      wall.name = "wall";
      wall.youngs_modulus_Pa *= 1000;
      const Hertz h = HertzImpact(EffectiveYoungs(c.material, wall), r,
                                  SphereMass(r, c.material.density_kg_m3), v);
      Scene s = ImpactScene(c.material, &wall, 2 * r, 1.0, 0.35);
      const double gap = 1e-6;
      s.walls = {PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 1, {}}};
      s.particles = {{0, {0, 0, r + gap}, {0, 0, -v}, {}, 2 * r}};
      s.domain_min_m = {-1, -1, -1};
      s.domain_max_m = {1, 1, 1};
      s.time.timestep_s = h.contact_time_s / 1000;
      Simulation sim(s, {.threads = 1});
      InitializeOrFail(sim);
      const ImpactRecord rec =
          RecordImpact(sim, gap / v + 2 * h.contact_time_s,
                       [r](const Simulation& q) { return r - q.particles().position_m[0].z; });
      CheckAgainstHertz(rec, h);
      CHECK(rec.max_overlap_m == Approx(c.rigid_reference.max_overlap_m).epsilon(0.01));
      CHECK(rec.max_force_N == Approx(c.rigid_reference.max_force_N).epsilon(0.01));
      CHECK(rec.ContactTime() == Approx(c.rigid_reference.contact_time_s).epsilon(0.01));
    }
  }
}

TEST_CASE("Chung & Ooi test 3: restitution out equals restitution in", "[physics]") {
  // Chung & Ooi 2011 test 3; docs/physics.md §4.1: R = 2.5 mm, v = 3.9 m/s onto a wall, μ = 0.
  // With the contact ending at δ = 0 the β(e) dashpot gives e_out = e exactly
  // (docs/physics.md §1.4, first column).
  const Material materials[] = {{"al_oxide", 380e9, 0.23, 4000}, {"cast_iron", 100e9, 0.25, 7000}};
  for (const Material& m : materials) {
    for (const double e : {0.2, 0.4, 0.6, 0.8, 1.0}) {
      DYNAMIC_SECTION(m.name << " e = " << e) {
        const double r = 2.5e-3, v = 3.9;
        Material wall = m;
        wall.name = "wall";
        wall.youngs_modulus_Pa *= 1000;
        const Hertz h = HertzImpact(EffectiveYoungs(m, wall), r, SphereMass(r, m.density_kg_m3), v);
        Scene s = ImpactScene(m, &wall, 2 * r, e, 0.0);
        const double gap = 1e-6;
        s.walls = {PlaneWall{"floor", {0, 0, 0}, {0, 0, 1}, 1, {}}};
        s.particles = {{0, {0, 0, r + gap}, {0, 0, -v}, {}, 2 * r}};
        s.domain_min_m = {-0.1, -0.1, -0.1};
        s.domain_max_m = {0.1, 0.1, 0.1};
        s.time.timestep_s = h.contact_time_s / 1000;
        Simulation sim(s, {.threads = 1});
        InitializeOrFail(sim);
        const ImpactRecord rec =
            RecordImpact(sim, gap / v + 2 * h.contact_time_s,
                         [r](const Simulation& q) { return r - q.particles().position_m[0].z; });
        REQUIRE(rec.end_s > 0);
        const double e_out = sim.particles().velocity_m_s[0].z / v;
        INFO("e_out = " << e_out);
        CHECK(e_out == Approx(e).epsilon(0.01));
      }
    }
  }
}
