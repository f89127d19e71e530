#include "core/bodies/clump_shapes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>

#include "core/limits/physical_limits.h"

namespace demcal::core {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kLambdaSteps = 16;

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

// Exact union volume of spheres with centres on one line (MassMethod::kCollinear).
double UnionVolume(const std::vector<ClumpSphere>& s) {
  MassPropertiesOptions o;
  o.method = MassMethod::kCollinear;
  MassProperties mp;
  std::string ignored;
  return ComputeMassProperties(s, 1.0, o, &mp, &ignored) ? mp.volume_m3 : std::nan("");
}

std::vector<double> EvenlySpaced(int n, double half_span) {
  std::vector<double> x(n, 0.0);
  for (int k = 0; k < n && n > 1; ++k) x[k] = -half_span + 2.0 * half_span * k / (n - 1);
  return x;
}

// n equal spheres of radius r, end spheres touching x = ±a.
std::vector<ClumpSphere> UniformChain(double a, double r, int n) {
  std::vector<ClumpSphere> s;
  for (double x : EvenlySpaced(n, a - r)) s.push_back({{x, 0, 0}, r});
  return s;
}

// Tapered chain: end spheres at x = ±X with radius a − X (touching x = ±a); the other n − 2
// spheres evenly spaced on [−P, P], P = λ X (n − 3)/(n − 1) (λ = 1: all n evenly spaced); radii
// on the elliptic profile r(x)² = r_e² + C (X² − x²) through the end spheres (r_e = a − X) and the
// innermost sphere(s) (|x| = p, radius rho). See the construction comment at ApproximateEllipsoid.
std::vector<ClumpSphere> TaperedChain(double a, double rho, int n, double end_x, double lambda) {
  std::vector<double> xs = EvenlySpaced(n - 2, lambda * end_x * (n - 3) / (n - 1));
  xs.insert(xs.begin(), -end_x);
  xs.push_back(end_x);
  double p2 = end_x * end_x;
  for (double x : xs) p2 = std::min(p2, x * x);
  const double re = a - end_x;
  const double span2 = end_x * end_x - p2;
  const double c = span2 > 0 ? (rho * rho - re * re) / span2 : 0.0;
  std::vector<ClumpSphere> s;
  for (double x : xs) s.push_back({{x, 0, 0}, std::sqrt(re * re + c * (end_x * end_x - x * x))});
  return s;
}

// Root of f on [lo, hi]: scans 64 sub-intervals from lo for the first sign change, then bisects.
// Returns false if f has no sign change on the scan grid or is not finite there.
bool FirstRoot(const std::function<double(double)>& f, double lo, double hi, double* root) {
  constexpr int kScan = 64;
  double x0 = lo, f0 = f(lo);
  for (int i = 1; i <= kScan; ++i) {
    const double x1 = lo + (hi - lo) * i / kScan;
    const double f1 = f(x1);
    if (!std::isfinite(f0) || !std::isfinite(f1)) return false;
    if (f0 == 0 || (f0 < 0) != (f1 < 0)) {
      double a = x0, b = x1, fa = f0;
      for (int it = 0; it < 200 && b - a > 1e-15 * std::max(std::abs(a), std::abs(b)); ++it) {
        const double m = 0.5 * (a + b);
        const double fm = f(m);
        if (fa == 0) break;
        if ((fa < 0) == (fm < 0))
          a = m, fa = fm;
        else
          b = m;
      }
      *root = fa == 0 ? a : 0.5 * (a + b);
      return true;
    }
    x0 = x1;
    f0 = f1;
  }
  return false;
}

// Tapered chain with union volume v: tries λ = 1 (evenly spaced), then compresses the interior
// (λ → 0, which for n = 4, 5 tends to the n = 3 chain) until the end position X ∈ [a − ρ, a) has a
// root of V_union(X) = v.
bool TaperedFit(double a, double rho, int n, double v, std::vector<ClumpSphere>* out) {
  const double x_lo = std::max(a - rho, 0.0), x_hi = a * (1 - 1e-9);
  if (!(x_hi > x_lo)) return false;
  for (int step = 0; step <= kLambdaSteps; ++step) {
    const double lambda = 1.0 - static_cast<double>(step) / kLambdaSteps;
    auto f = [&](double end_x) { return UnionVolume(TaperedChain(a, rho, n, end_x, lambda)) - v; };
    double x = 0;
    if (FirstRoot(f, x_lo, x_hi, &x)) {
      *out = TaperedChain(a, rho, n, x, lambda);
      return true;
    }
  }
  return false;
}

Vec3 Extents(const std::vector<ClumpSphere>& s) {
  Vec3 lo = s[0].centre_m, hi = s[0].centre_m;
  for (const auto& sp : s) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], sp.centre_m[a] - sp.radius_m);
      hi[a] = std::max(hi[a], sp.centre_m[a] + sp.radius_m);
    }
  }
  return hi - lo;
}

// Fills the clump-side figures and the errors against out->target_*.
void Report(ShapeApproximation* out) {
  out->clump_volume_m3 = UnionVolume(out->spheres);
  out->volume_error = out->clump_volume_m3 / out->target_volume_m3 - 1.0;
  out->clump_extents_m = Extents(out->spheres);
  out->target_ratios = AspectRatiosFromExtents(out->target_extents_m);
  out->clump_ratios = AspectRatiosFromExtents(out->clump_extents_m);
  out->aspect_ratio_error =
      out->clump_ratios.long_over_short / out->target_ratios.long_over_short - 1.0;
  // Balls centred on one axis intersect iff their axis intervals do.
  std::vector<ClumpSphere> s = out->spheres;
  std::sort(s.begin(), s.end(), [](auto& p, auto& q) { return p.centre_m.x < q.centre_m.x; });
  double reach = s[0].centre_m.x + s[0].radius_m;
  out->connected = true;
  for (size_t k = 1; k < s.size(); ++k) {
    // Tolerance: tangent spheres (e.g. 3 spheres for a 3:1 spheroid) count as connected.
    if (s[k].centre_m.x - s[k].radius_m > reach + 1e-9 * out->clump_extents_m.x) {
      out->connected = false;
    }
    reach = std::max(reach, s[k].centre_m.x + s[k].radius_m);
  }
}

}  // namespace

// Construction (spheres on the long axis x, symmetric about the origin). Let ρ = √(bc): the
// spheroid (a, ρ, ρ) has the ellipsoid's volume V = 4/3 π a b c, and a chain of spheres on one
// axis is axisymmetric, so it is the spheroid that the chain can match.
//  * n = 1: the equal-volume sphere, r = (abc)^{1/3}; its length 2r cannot equal 2a.
//  * n ≥ 3, "tapered" chain. End spheres centred at ±X with radius a − X, so they touch the tips
//    and the overall length is 2a. The other n − 2 centres are evenly spaced on [−P, P]
//    (P = X (n − 3)/(n − 1) makes all n evenly spaced). Radii follow an elliptic profile
//    r(x)² = r_e² + C (X² − x²) through the end spheres (r_e = a − X) and the innermost
//    sphere(s) at |x| = p, whose radius is ρ: C = (ρ² − r_e²)/(X² − p²). So the width is 2ρ.
//    The one unknown X ∈ [a − ρ, a) (X = a − ρ: all radii ρ) comes from root-finding on the
//    exact union volume, V_union(X) = V: volume, length and width all match the spheroid.
//    If no X works with even spacing (happens for even n and a nearly spherical target, where the
//    two middle spheres sit too far apart), P is shrunk in 16 steps towards 0, where n = 4 and 5
//    become the n = 3 chain with coincident middle spheres.
//  * Otherwise (always for n = 2, which has no width freedom, and for targets too elongated for
//    n spheres of radius ≤ ρ), the "uniform" chain: n equal spheres of radius r, end spheres
//    touching the tips, r from V_union(r) = V. Volume and length match; the width does not (the
//    aspect-ratio error says by how much) and the spheres may not touch (`connected`).
// For a sphere target every construction puts all spheres at the origin with radius a.
bool CheckEllipsoidSemiAxes(const Vec3& semi_axes, std::string* error) {
  const double a = semi_axes.x, b = semi_axes.y, c = semi_axes.z;
  std::ostringstream os, given;
  given << "[" << a << ", " << b << ", " << c << "]";
  if (!(a >= b && b >= c && c > 0))
    os << "must be [a, b, c] with a >= b >= c > 0, got " << given.str();
  else if (!limits::kClumpLength.Contains(a) || !limits::kClumpLength.Contains(c))
    os << "= " << given.str() << " is outside the allowed range " << limits::kClumpLength.Text()
       << " (any one length unit)";
  else if (!limits::kClumpAspectRatio.Contains(a / c))
    os << "= " << given.str() << " has the aspect ratio a/c = " << a / c
       << ", outside the allowed range " << limits::kClumpAspectRatio.Text() << " (at most "
       << kMaxEllipsoidSpheres << " spheres on the long axis)";
  else
    return true;
  return Fail(error, os.str());
}

bool ApproximateEllipsoid(const Vec3& semi_axes_m, int n_spheres, ShapeApproximation* out,
                          std::string* error) {
  const double a = semi_axes_m.x, b = semi_axes_m.y, c = semi_axes_m.z;
  if (n_spheres < 1 || n_spheres > kMaxEllipsoidSpheres) {
    std::ostringstream os;
    os << "ApproximateEllipsoid: n_spheres = " << n_spheres << " must be in 1.."
       << kMaxEllipsoidSpheres;
    return Fail(error, os.str());
  }
  std::string why;
  if (!CheckEllipsoidSemiAxes(semi_axes_m, &why))
    return Fail(error, "ApproximateEllipsoid: semi-axes " + why);
  ShapeApproximation r;
  r.target_volume_m3 = 4.0 / 3.0 * kPi * a * b * c;
  r.target_extents_m = 2.0 * semi_axes_m;
  const double rho = std::sqrt(b * c);
  const double v = r.target_volume_m3;
  if (n_spheres == 1) {
    r.spheres = {{{0, 0, 0}, std::cbrt(a * b * c)}};
    r.construction = "single";
  } else if (n_spheres >= 3 && TaperedFit(a, rho, n_spheres, v, &r.spheres)) {
    r.construction = "tapered";
  } else {
    // V(r = a) ≥ v (a single sphere of radius a) and V(r → 0) → 0; scan down from r = a.
    auto f = [&](double t) { return UnionVolume(UniformChain(a, a - t, n_spheres)) - v; };
    double t = 0;
    if (!FirstRoot(f, 0.0, a * (1 - 1e-9), &t)) {
      if (std::abs(f(0.0)) > 1e-12 * v) {
        return Fail(error, "ApproximateEllipsoid: no uniform chain matches the volume");
      }
      t = 0;  // a sphere: V(a) = v up to round-off
    }
    r.spheres = UniformChain(a, a - t, n_spheres);
    r.construction = "uniform";
  }
  Report(&r);
  *out = std::move(r);
  return true;
}

bool ComputeMeshMassProperties(const std::vector<Triangle>& triangles, double density_kg_m3,
                               MeshMassProperties* out, std::string* error) {
  if (triangles.empty()) return Fail(error, "mesh: triangle list is empty");
  if (!std::isfinite(density_kg_m3) || density_kg_m3 <= 0) {
    std::ostringstream os;
    os << "mesh: density_kg_m3 = " << density_kg_m3 << " must be finite and > 0";
    return Fail(error, os.str());
  }
  Vec3 lo = triangles[0][0], hi = lo;
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (const Vec3& p : triangles[t]) {
      if (!IsFinite(p)) {
        std::ostringstream os;
        os << "mesh: triangles[" << t << "] has a non-finite vertex";
        return Fail(error, os.str());
      }
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    }
  }
  const Vec3 ref = 0.5 * (lo + hi);  // tetrahedra apex: the box centre keeps round-off small
  double six_vol = 0, area2 = 0;
  Vec3 normal_sum;
  Eigen::Vector3d first6 = Eigen::Vector3d::Zero();   // 24 ∫(x−ref)dV
  Eigen::Matrix3d second6 = Eigen::Matrix3d::Zero();  // 120 ∫(x−ref)(x−ref)ᵀdV
  for (const Triangle& tri : triangles) {
    const Vec3 v0 = tri[0] - ref, v1 = tri[1] - ref, v2 = tri[2] - ref;
    const Vec3 n = Cross(v1 - v0, v2 - v0);
    normal_sum += n;
    area2 += Norm(n);
    const double det = Dot(v0, Cross(v1, v2));  // 6 × signed tetrahedron volume
    const Eigen::Vector3d e0(v0.x, v0.y, v0.z), e1(v1.x, v1.y, v1.z), e2(v2.x, v2.y, v2.z);
    const Eigen::Vector3d s = e0 + e1 + e2;
    six_vol += det;
    first6 += det * s;
    second6 +=
        det * (e0 * e0.transpose() + e1 * e1.transpose() + e2 * e2.transpose() + s * s.transpose());
  }
  if (!(area2 > 0) || Norm(normal_sum) > 1e-8 * area2) {
    std::ostringstream os;
    os << "mesh: not closed (|sum of area vectors| / total area = "
       << (area2 > 0 ? Norm(normal_sum) / area2 : 0.0) << ")";
    return Fail(error, os.str());
  }
  MeshMassProperties m;
  m.inverted = six_vol < 0;
  const double sign = m.inverted ? -1.0 : 1.0;
  const double vol = sign * six_vol / 6.0;
  if (!(vol > 0)) return Fail(error, "mesh: enclosed volume is zero");
  const Eigen::Vector3d c = sign * first6 / 24.0 / vol;  // centroid relative to ref
  const Eigen::Matrix3d second = sign * second6 / 120.0 - vol * c * c.transpose();
  m.volume_m3 = vol;
  m.mass_kg = density_kg_m3 * vol;
  m.centroid_m = ref + Vec3{c.x(), c.y(), c.z()};
  m.inertia_kg_m2 = density_kg_m3 * (second.trace() * Eigen::Matrix3d::Identity() - second);
  Eigen::Matrix3d axes;
  if (!PrincipalFrame(m.inertia_kg_m2, &m.principal_inertia_kg_m2, &axes)) {
    return Fail(error, "mesh: inertia diagonalisation failed");
  }
  m.mesh_from_principal = FromRotationMatrix(axes);
  Eigen::Vector3d plo = Eigen::Vector3d::Constant(INFINITY), phi = -plo;
  for (const Triangle& tri : triangles) {
    for (const Vec3& p : tri) {
      const Vec3 d = p - m.centroid_m;
      const Eigen::Vector3d q = axes.transpose() * Eigen::Vector3d(d.x, d.y, d.z);
      plo = plo.cwiseMin(q);
      phi = phi.cwiseMax(q);
    }
  }
  m.principal_extents_m = {phi.x() - plo.x(), phi.y() - plo.y(), phi.z() - plo.z()};
  // Solid ellipsoid: I1 = m (b² + c²)/5 etc. ⇒ a² = 5 (I2 + I3 − I1) / (2m), ...
  const Vec3& i = m.principal_inertia_kg_m2;
  const double k = 5.0 / (2.0 * m.mass_kg);
  std::array<double, 3> ax = {std::sqrt(std::max(0.0, k * (i.y + i.z - i.x))),
                              std::sqrt(std::max(0.0, k * (i.x + i.z - i.y))),
                              std::sqrt(std::max(0.0, k * (i.x + i.y - i.z)))};
  std::sort(ax.begin(), ax.end(), std::greater<>());
  const double ell_vol = 4.0 / 3.0 * kPi * ax[0] * ax[1] * ax[2];
  if (!(ell_vol > 0))
    return Fail(error, "mesh: degenerate (flat) inertia, no equivalent ellipsoid");
  const double scale = std::cbrt(vol / ell_vol);
  m.equivalent_semi_axes_m = {scale * ax[0], scale * ax[1], scale * ax[2]};
  *out = m;
  return true;
}

bool ApproximateMesh(const std::vector<Triangle>& triangles, int n_spheres, MeshApproximation* out,
                     std::string* error) {
  MeshApproximation r;
  if (!ComputeMeshMassProperties(triangles, 1.0, &r.mesh, error)) return false;
  if (!ApproximateEllipsoid(r.mesh.equivalent_semi_axes_m, n_spheres, &r.shape, error)) {
    return false;
  }
  // Errors against the mesh itself rather than the intermediate ellipsoid.
  r.shape.target_volume_m3 = r.mesh.volume_m3;
  r.shape.target_extents_m = r.mesh.principal_extents_m;
  Report(&r.shape);
  *out = std::move(r);
  return true;
}

}  // namespace demcal::core
