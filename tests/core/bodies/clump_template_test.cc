#include "core/bodies/clump_template.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/math/random.h"

using namespace demcal::core;

namespace {

constexpr double kPi = std::numbers::pi;

double SphereVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

// Lens (intersection) of two spheres of radius R at centre distance d ≤ 2R subtracted from the
// two spheres: V = 2·(4/3)πR³ − π(4R + d)(2R − d)²/12 (docs/physics.md §7.1; Weisstein, MathWorld
// "Sphere-Sphere Intersection").
double LensUnionVolume(double r, double d) {
  return 2 * SphereVolume(r) - kPi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12;
}

// ∫_lo^hi p(z) dz for a polynomial with coefficients c[0] + c[1] z + ...
double IntegratePoly(const std::vector<double>& c, double lo, double hi) {
  double s = 0;
  for (size_t k = 0; k < c.size(); ++k) {
    s += c[k] * (std::pow(hi, k + 1) - std::pow(lo, k + 1)) / (k + 1);
  }
  return s;
}

std::vector<double> Mul(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> c(a.size() + b.size() - 1, 0.0);
  for (size_t i = 0; i < a.size(); ++i) {
    for (size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  }
  return c;
}

// Analytic mass properties of two equal overlapping spheres (radius R, centres at s = ±d/2 on an
// axis, density ρ). By symmetry each half (s ≥ 0) is the sphere centred at h = d/2 cut at s = 0:
// slices z = s − h ∈ [−h, R] of area π(R² − z²). Volume, ∫s²dV and the slice second moment
// ∫πρ⁴/4 are polynomial integrals in z.
struct TwoSphereAnalytic {
  double volume, axial, transverse;  // inertia about the centre: axis, any perpendicular line
};
TwoSphereAnalytic TwoSpheres(double r, double d, double density) {
  const double h = d / 2;
  const std::vector<double> area = {kPi * r * r, 0, -kPi};  // π(R² − z²)
  const std::vector<double> s2 = {h * h, 2 * h, 1};         // (z + h)²
  const double v_half = IntegratePoly(area, -h, r);
  const double ss_half = IntegratePoly(Mul(s2, area), -h, r);
  const double disc_half = IntegratePoly(Mul(area, area), -h, r) / (4 * kPi);  // ∫πρ⁴/4
  return {2 * v_half, density * 2 * (2 * disc_half), density * 2 * (ss_half + disc_half)};
}

std::vector<ClumpSphere> TwoOnAxis(double r, double d, const Vec3& centre, const Vec3& axis) {
  const Vec3 u = axis / Norm(axis);
  return {{centre - 0.5 * d * u, r}, {centre + 0.5 * d * u, r}};
}

// Inertia about the line through `c` along unit `u`.
double AboutAxis(const Eigen::Matrix3d& inertia, const Vec3& u) {
  const Eigen::Vector3d e(u.x, u.y, u.z);
  return e.dot(inertia * e);
}

}  // namespace

TEST_CASE("clump: one sphere has exactly the sphere's mass and inertia", "[clump][unit]") {
  const double r = 1.7e-3, rho = 2650;
  ClumpTemplate t;
  std::string err;
  REQUIRE(BuildClumpTemplate({{{0.3, -0.2, 5.0}, r}}, rho, {}, &t, &err));
  const double m = rho * SphereVolume(r);
  CHECK(t.method_used == MassMethod::kExactSum);
  CHECK(t.mass_kg == Approx(m).epsilon(1e-15));
  CHECK(t.volume_m3 == Approx(SphereVolume(r)).epsilon(1e-15));
  for (int a = 0; a < 3; ++a) {
    CHECK(t.principal_inertia_kg_m2[a] == Approx(0.4 * m * r * r).epsilon(1e-15));
  }
  REQUIRE(t.spheres.size() == 1);
  CHECK(Norm(t.spheres[0].centre_m) == 0.0);
  CHECK(t.input_centre_of_mass_m == Vec3{0.3, -0.2, 5.0});
  CHECK(t.EquivalentVolumeDiameter() == Approx(2 * r).epsilon(1e-15));
  CHECK(t.BoundingRadius() == Approx(r).epsilon(1e-15));
}

TEST_CASE("clump: non-overlapping spheres equal the parallel-axis sum", "[clump][unit]") {
  // docs/physics.md §7.1: m = Σρ(4/3)πr³, c = Σ m_k x_k / m, I = Σ[(2/5) m_k r_k² 𝟙 + m_k(|d|²𝟙 − d
  // dᵀ)].
  const std::vector<ClumpSphere> s = {{{0, 0, 0}, 1.0}, {{3, 0.5, 0}, 0.5}, {{-1, 2.5, 1}, 0.8}};
  const double rho = 3.0;
  double m = 0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& sp : s) {
    m += rho * SphereVolume(sp.radius_m);
    c += rho * SphereVolume(sp.radius_m) *
         Eigen::Vector3d(sp.centre_m.x, sp.centre_m.y, sp.centre_m.z);
  }
  c /= m;
  Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
  for (const auto& sp : s) {
    const double mk = rho * SphereVolume(sp.radius_m);
    const Eigen::Vector3d d = Eigen::Vector3d(sp.centre_m.x, sp.centre_m.y, sp.centre_m.z) - c;
    expected += 0.4 * mk * sp.radius_m * sp.radius_m * Eigen::Matrix3d::Identity() +
                mk * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  MassProperties mp;
  std::string err;
  REQUIRE(ComputeMassProperties(s, rho, {}, &mp, &err));
  CHECK(mp.method_used == MassMethod::kExactSum);
  CHECK(mp.mass_kg == Approx(m).epsilon(1e-14));
  CHECK((Eigen::Vector3d(mp.centre_of_mass_m.x, mp.centre_of_mass_m.y, mp.centre_of_mass_m.z) - c)
            .norm() < 1e-14);
  CHECK((mp.inertia_kg_m2 - expected).norm() < 1e-13 * expected.norm());
}

TEST_CASE("clump: two overlapping spheres match the lens formula and analytic inertia",
          "[clump][physics]") {
  const double r = 1.5e-3, rho = 2500;
  const Vec3 centre{0.01, -0.02, 0.003};
  const Vec3 axis{1, 2, -0.5};  // not grid-aligned
  const Vec3 u = axis / Norm(axis);
  const Vec3 perp = Cross(u, Vec3{0, 0, 1}) / Norm(Cross(u, Vec3{0, 0, 1}));
  for (double frac : {0.1, 0.5, 1.0, 1.6, 1.95}) {
    const double d = frac * r;
    const auto s = TwoOnAxis(r, d, centre, axis);
    const TwoSphereAnalytic exact = TwoSpheres(r, d, rho);
    INFO("d/R = " << frac);
    // The polynomial integration reproduces the lens formula (two independent derivations).
    REQUIRE(exact.volume == Approx(LensUnionVolume(r, d)).epsilon(1e-12));

    struct Case {
      MassMethod method;
      double tol;
    };
    // Collinear is exact; voxel at the default divisions and Monte Carlo (2e6 points, ~0.1 %
    // standard error) must be within the 0.5 % asked of the clump builder.
    for (const Case c : {Case{MassMethod::kAuto, 1e-12}, Case{MassMethod::kVoxel, 5e-3},
                         Case{MassMethod::kMonteCarlo, 5e-3}}) {
      MassPropertiesOptions o;
      o.method = c.method;
      MassProperties mp;
      std::string err;
      REQUIRE(ComputeMassProperties(s, rho, o, &mp, &err));
      INFO("method " << MassMethodName(mp.method_used));
      if (c.method == MassMethod::kAuto) CHECK(mp.method_used == MassMethod::kCollinear);
      CHECK(mp.volume_m3 == Approx(exact.volume).epsilon(c.tol));
      CHECK(mp.mass_kg == Approx(rho * exact.volume).epsilon(c.tol));
      CHECK(Norm(mp.centre_of_mass_m - centre) < c.tol * r);
      CHECK(AboutAxis(mp.inertia_kg_m2, u) == Approx(exact.axial).epsilon(c.tol));
      CHECK(AboutAxis(mp.inertia_kg_m2, perp) == Approx(exact.transverse).epsilon(c.tol));
    }
  }
}

TEST_CASE("clump: ignoring overlaps overestimates the union by 18.5 % (two unit spheres, d = 1)",
          "[clump][physics]") {
  // docs/physics.md §7.1: union 7.0686 vs naive 8.3776.
  const auto s = TwoOnAxis(1.0, 1.0, {0, 0, 0}, {0, 0, 1});
  MassPropertiesOptions naive;
  naive.method = MassMethod::kExactSum;
  MassProperties a, b;
  std::string err;
  REQUIRE(ComputeMassProperties(s, 1.0, naive, &a, &err));
  REQUIRE(ComputeMassProperties(s, 1.0, {}, &b, &err));
  CHECK(a.volume_m3 == Approx(8.3776).epsilon(1e-5));
  CHECK(b.volume_m3 == Approx(7.0686).epsilon(1e-5));
  CHECK(a.volume_m3 / b.volume_m3 - 1 == Approx(0.185).epsilon(2e-3));
}

TEST_CASE("clump: voxel lens volume within 0.5 % for random placements", "[clump][physics]") {
  Rng rng(2024);
  for (int i = 0; i < 40; ++i) {
    const double r = rng.Uniform(0.5e-3, 2e-3), d = rng.Uniform(0.0, 2.0) * r;
    const Vec3 centre{rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)};
    const Vec3 axis{rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(0.1, 1)};
    MassPropertiesOptions o;
    o.method = MassMethod::kVoxel;
    MassProperties mp;
    std::string err;
    REQUIRE(ComputeMassProperties(TwoOnAxis(r, d, centre, axis), 1.0, o, &mp, &err));
    INFO("r = " << r << ", d/r = " << d / r);
    CHECK(mp.volume_m3 == Approx(LensUnionVolume(r, d)).epsilon(5e-3));
  }
}

TEST_CASE("clump: non-collinear overlapping clump uses voxels; Monte Carlo agrees",
          "[clump][unit]") {
  const std::vector<ClumpSphere> s = {
      {{0, 0, 0}, 1.0}, {{1.2, 0, 0}, 0.8}, {{0.5, 1.0, 0.2}, 0.7}, {{0.4, 0.3, 0.9}, 0.6}};
  MassProperties vox, fine, mc;
  std::string err;
  REQUIRE(ComputeMassProperties(s, 1.0, {}, &vox, &err));
  CHECK(vox.method_used == MassMethod::kVoxel);
  MassPropertiesOptions o;
  o.method = MassMethod::kVoxel;
  o.voxel_divisions = 150;
  REQUIRE(ComputeMassProperties(s, 1.0, o, &fine, &err));
  o.method = MassMethod::kMonteCarlo;
  REQUIRE(ComputeMassProperties(s, 1.0, o, &mc, &err));
  CHECK(vox.volume_m3 == Approx(fine.volume_m3).epsilon(5e-3));
  CHECK(mc.volume_m3 == Approx(fine.volume_m3).epsilon(5e-3));
  CHECK((vox.inertia_kg_m2 - fine.inertia_kg_m2).norm() < 5e-3 * fine.inertia_kg_m2.norm());
  CHECK((mc.inertia_kg_m2 - fine.inertia_kg_m2).norm() < 5e-3 * fine.inertia_kg_m2.norm());
  // The union is smaller than the naive sum.
  double naive = 0;
  for (const auto& sp : s) naive += SphereVolume(sp.radius_m);
  CHECK(fine.volume_m3 < naive);
}

TEST_CASE("clump: principal frame of a rotated, shifted clump is recovered", "[clump][unit]") {
  // Built in its principal frame: mirror-symmetric in x, y, z with distinct moments.
  const std::vector<ClumpSphere> body = {
      {{2, 0, 0}, 0.6}, {{-2, 0, 0}, 0.6}, {{0, 1, 0}, 0.5}, {{0, -1, 0}, 0.5}, {{0, 0, 0}, 0.4}};
  ClumpTemplate t0;
  std::string err;
  REQUIRE(BuildClumpTemplate(body, 1000, {}, &t0, &err));
  const Vec3 m0 = t0.principal_inertia_kg_m2;
  REQUIRE(m0.x < m0.y);
  REQUIRE(m0.y < m0.z);
  // Axis 1 (smallest moment) is the long x axis.
  CHECK(std::abs(t0.spheres[0].centre_m.x) == Approx(2.0).epsilon(1e-12));

  Rng rng(5);
  for (int i = 0; i < 20; ++i) {
    const Quaternion q = Quaternion::FromAxisAngle(
        {rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-1, 1)}, rng.Uniform(-3, 3));
    const Vec3 shift{rng.Uniform(-5, 5), rng.Uniform(-5, 5), rng.Uniform(-5, 5)};
    std::vector<ClumpSphere> moved;
    for (const auto& sp : body) moved.push_back({shift + Rotate(q, sp.centre_m), sp.radius_m});
    ClumpTemplate t;
    REQUIRE(BuildClumpTemplate(moved, 1000, {}, &t, &err));
    for (int a = 0; a < 3; ++a) {
      CHECK(t.principal_inertia_kg_m2[a] == Approx(m0[a]).epsilon(1e-12));
    }
    CHECK(Norm(t.input_centre_of_mass_m - shift) < 1e-12);
    // Principal axes = rotated body axes up to a sign each: |Aᵀ R| = 𝟙.
    const Eigen::Matrix3d m =
        ToRotationMatrix(t.input_from_principal).transpose() * ToRotationMatrix(q);
    CHECK((m.cwiseAbs() - Eigen::Matrix3d::Identity()).norm() < 1e-10);
    // The template maps back onto the input spheres.
    for (size_t k = 0; k < moved.size(); ++k) {
      const Vec3 back =
          t.input_centre_of_mass_m + Rotate(t.input_from_principal, t.spheres[k].centre_m);
      CHECK(Norm(back - moved[k].centre_m) < 1e-12);
    }
  }
}

TEST_CASE("clump: shape descriptors of two overlapping spheres", "[clump][unit]") {
  const double r = 1.0, d = 1.0;
  ClumpTemplate t;
  std::string err;
  REQUIRE(BuildClumpTemplate(TwoOnAxis(r, d, {1, 2, 3}, {1, 1, 0}), 1.0, {}, &t, &err));
  CHECK(t.EquivalentVolumeDiameter() == Approx(std::cbrt(6 * LensUnionVolume(r, d) / kPi)));
  CHECK(t.BoundingRadius() == Approx(r + d / 2).epsilon(1e-12));
  const Vec3 e = t.BoundingBoxExtents();
  CHECK(e.x == Approx(2 * r + d).epsilon(1e-12));  // axis 1 = the line of centres
  CHECK(e.y == Approx(2 * r).epsilon(1e-12));
  CHECK(e.z == Approx(2 * r).epsilon(1e-12));
  const AspectRatios ar = t.ShapeAspectRatios();
  CHECK(ar.elongation == Approx(2 * r / (2 * r + d)).epsilon(1e-12));
  CHECK(ar.flatness == Approx(1.0).epsilon(1e-12));
  CHECK(ar.long_over_short == Approx((2 * r + d) / (2 * r)).epsilon(1e-12));
}

TEST_CASE("clump: invalid input is rejected with a clear message", "[clump][unit]") {
  const double nan = std::nan("");
  struct Case {
    std::vector<ClumpSphere> spheres;
    double density;
    MassPropertiesOptions options;
    const char* expect;
  };
  MassPropertiesOptions collinear, bad_div, tiny_grid, mc;
  collinear.method = MassMethod::kCollinear;
  bad_div.voxel_divisions = 0;
  tiny_grid.method = MassMethod::kVoxel;
  tiny_grid.max_voxel_columns = 10;
  mc.method = MassMethod::kMonteCarlo;
  mc.monte_carlo_points = 1000;
  const std::vector<ClumpSphere> two = {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}};
  const std::vector<Case> cases = {
      {{}, 1, {}, "sphere list is empty"},
      {{{{0, 0, 0}, 0.0}}, 1, {}, "spheres[0].radius_m = 0 must be finite and > 0"},
      {{{{0, 0, 0}, 1}, {{3, 0, 0}, -1}}, 1, {}, "spheres[1].radius_m = -1"},
      {{{{0, nan, 0}, 1}}, 1, {}, "spheres[0].centre_m is not finite"},
      {{{{0, 0, 0}, nan}}, 1, {}, "spheres[0].radius_m = nan"},
      {{{{0, 0, 0}, 1}}, 0, {}, "density_kg_m3 = 0 must be finite and > 0"},
      {{{{0, 0, 0}, 1}}, 1, bad_div, "voxel_divisions = 0 must be >= 1"},
      {{{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{0, 1, 0}, 1}}, 1, collinear, "collinear"},
      {two, 1, tiny_grid, "exceeds max_voxel_columns = 10"},
      // Two specks 1 m apart: 1000 Monte Carlo points all miss.
      {{{{0, 0, 0}, 1e-4}, {{1, 0, 0}, 1e-4}}, 1, mc, "integrated volume is zero"},
  };
  for (const Case& c : cases) {
    MassProperties mp;
    ClumpTemplate t;
    std::string err1, err2;
    CHECK_FALSE(ComputeMassProperties(c.spheres, c.density, c.options, &mp, &err1));
    CHECK_FALSE(BuildClumpTemplate(c.spheres, c.density, c.options, &t, &err2));
    CHECK_THAT(err1, Catch::Contains(c.expect));
    CHECK(err1 == err2);
  }
}
