#include "core/bodies/clump_template.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/math/random.h"

namespace demcal::core {
namespace {

constexpr double kPi = std::numbers::pi;

// Raw volume moments about a reference point p: V = ∫dV, s = ∫(x−p)dV, m = ∫(x−p)(x−p)ᵀdV.
struct Moments {
  Vec3 reference;
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  int64_t samples = 0;
};

Eigen::Vector3d E(const Vec3& v) { return {v.x, v.y, v.z}; }

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

bool ValidateSpheres(const std::vector<ClumpSphere>& spheres, std::string* error) {
  if (spheres.empty()) return Fail(error, "clump: sphere list is empty");
  for (size_t k = 0; k < spheres.size(); ++k) {
    std::ostringstream os;
    os << "clump: spheres[" << k << "]";
    if (!IsFinite(spheres[k].centre_m)) return Fail(error, os.str() + ".centre_m is not finite");
    const double r = spheres[k].radius_m;
    if (!std::isfinite(r) || r <= 0) {
      os << ".radius_m = " << r << " must be finite and > 0";
      return Fail(error, os.str());
    }
  }
  return true;
}

bool AnyOverlap(const std::vector<ClumpSphere>& s) {
  for (size_t i = 0; i < s.size(); ++i) {
    for (size_t j = i + 1; j < s.size(); ++j) {
      const double rr = s[i].radius_m + s[j].radius_m;
      if (Norm2(s[i].centre_m - s[j].centre_m) < rr * rr) return true;
    }
  }
  return false;
}

// Finds a line containing every centre. Returns false if the centres are not collinear (relative
// tolerance 1e-12 of the clump size). Coincident centres give the x axis.
bool CollinearAxis(const std::vector<ClumpSphere>& s, Vec3* origin, Vec3* axis) {
  *origin = s[0].centre_m;
  double far2 = 0, size = 0;
  Vec3 far = *origin;
  for (const auto& sp : s) {
    size = std::max(size, sp.radius_m);
    const double d2 = Norm2(sp.centre_m - *origin);
    if (d2 > far2) far2 = d2, far = sp.centre_m;
  }
  size = std::max(size, std::sqrt(far2));
  *axis = far2 > 0 ? (far - *origin) / std::sqrt(far2) : Vec3{1, 0, 0};
  for (const auto& sp : s) {
    const Vec3 d = sp.centre_m - *origin;
    if (Norm(d - Dot(d, *axis) * *axis) > 1e-12 * size) return false;
  }
  return true;
}

Moments ExactSum(const std::vector<ClumpSphere>& s) {
  Moments m;
  m.reference = s[0].centre_m;
  for (const auto& sp : s) {
    const double v = 4.0 / 3.0 * kPi * sp.radius_m * sp.radius_m * sp.radius_m;
    const Eigen::Vector3d d = E(sp.centre_m - m.reference);
    m.volume += v;
    m.first += v * d;
    // ∫ over a ball of (x−c)(x−c)ᵀ = V r²/5 𝟙.
    m.second +=
        v * (d * d.transpose() + sp.radius_m * sp.radius_m / 5.0 * Eigen::Matrix3d::Identity());
  }
  return m;
}

// Solid of revolution about `axis` (coordinate s from `origin`): the squared profile is
// ρ²(s) = max_k (r_k² − (s − s_k)²)₊. Two parabolas with the same leading coefficient cross at
// most once, so between the sorted breakpoints {s_k ± r_k, pairwise crossings} one sphere
// dominates and every integrand is a polynomial of degree ≤ 4: 4-point Gauss–Legendre is exact.
Moments Collinear(const std::vector<ClumpSphere>& s, const Vec3& origin, const Vec3& axis) {
  const size_t n = s.size();
  std::vector<double> pos(n), r2(n), breaks;
  for (size_t k = 0; k < n; ++k) {
    pos[k] = Dot(s[k].centre_m - origin, axis);
    r2[k] = s[k].radius_m * s[k].radius_m;
    breaks.push_back(pos[k] - s[k].radius_m);
    breaks.push_back(pos[k] + s[k].radius_m);
  }
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      if (pos[i] == pos[j]) continue;
      breaks.push_back((r2[i] - r2[j] + pos[j] * pos[j] - pos[i] * pos[i]) /
                       (2 * (pos[j] - pos[i])));
    }
  }
  std::sort(breaks.begin(), breaks.end());
  constexpr std::array<double, 4> kNode = {-0.8611363115940526, -0.3399810435848563,
                                           0.3399810435848563, 0.8611363115940526};
  constexpr std::array<double, 4> kWeight = {0.3478548451374538, 0.6521451548625461,
                                             0.6521451548625461, 0.3478548451374538};
  double vol = 0, s1 = 0, s2 = 0, disc = 0;  // ∫A, ∫sA, ∫s²A, ∫πρ⁴/4 (transverse 2nd moment)
  for (size_t b = 0; b + 1 < breaks.size(); ++b) {
    const double lo = breaks[b], hi = breaks[b + 1];
    if (hi <= lo) continue;
    // Identify the dominant sphere at the midpoint and integrate its parabola.
    const double mid = 0.5 * (lo + hi);
    int dom = -1;
    double best = 0;
    for (size_t k = 0; k < n; ++k) {
      const double p = r2[k] - (mid - pos[k]) * (mid - pos[k]);
      if (p > best) best = p, dom = static_cast<int>(k);
    }
    if (dom < 0) continue;  // a gap between separated spheres
    for (int g = 0; g < 4; ++g) {
      const double x = mid + 0.5 * (hi - lo) * kNode[g];
      const double w = 0.5 * (hi - lo) * kWeight[g];
      const double rho2 = r2[dom] - (x - pos[dom]) * (x - pos[dom]);
      const double area = kPi * rho2;
      vol += w * area;
      s1 += w * x * area;
      s2 += w * x * x * area;
      disc += w * kPi * rho2 * rho2 / 4.0;
    }
  }
  Moments m;
  m.reference = origin;
  const Eigen::Vector3d u = E(axis);
  m.volume = vol;
  m.first = s1 * u;
  m.second = s2 * u * u.transpose() + disc * (Eigen::Matrix3d::Identity() - u * u.transpose());
  return m;
}

void BoundingBox(const std::vector<ClumpSphere>& s, Vec3* lo, Vec3* hi) {
  const Vec3 r0{s[0].radius_m, s[0].radius_m, s[0].radius_m};
  *lo = s[0].centre_m - r0;
  *hi = s[0].centre_m + r0;
  for (const auto& sp : s) {
    for (int a = 0; a < 3; ++a) {
      (*lo)[a] = std::min((*lo)[a], sp.centre_m[a] - sp.radius_m);
      (*hi)[a] = std::max((*hi)[a], sp.centre_m[a] + sp.radius_m);
    }
  }
}

// Cell-centre voxel integration. Each (x, y) column is summed in closed form: the cells whose
// centres lie inside sphere k form an index range, the union of ranges is merged, and the sums
// of z and z² over an arithmetic run of n cells are n·z̄ and n·z̄² + dz²·n(n²−1)/12.
bool Voxel(const std::vector<ClumpSphere>& s, const MassPropertiesOptions& o, Moments* m,
           std::string* error) {
  double r_min = s[0].radius_m;
  for (const auto& sp : s) r_min = std::min(r_min, sp.radius_m);
  const double h = r_min / o.voxel_divisions;
  Vec3 lo, hi;
  BoundingBox(s, &lo, &hi);
  int64_t count[3];
  for (int a = 0; a < 3; ++a) count[a] = static_cast<int64_t>(std::ceil((hi[a] - lo[a]) / h));
  if (count[0] * count[1] > o.max_voxel_columns) {
    std::ostringstream os;
    os << "clump: voxel grid of " << count[0] << " x " << count[1] << " columns exceeds "
       << "max_voxel_columns = " << o.max_voxel_columns
       << "; lower voxel_divisions or use Monte Carlo";
    return Fail(error, os.str());
  }
  m->reference = 0.5 * (lo + hi);
  // Cell-centre coordinates relative to the reference point.
  auto centre = [&](int a, int64_t i) { return lo[a] + (i + 0.5) * h - m->reference[a]; };
  const double dv = h * h * h;
  std::vector<std::pair<int64_t, int64_t>> runs;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  int64_t cells = 0;
  for (int64_t i = 0; i < count[0]; ++i) {
    const double x = centre(0, i);
    for (int64_t j = 0; j < count[1]; ++j) {
      const double y = centre(1, j);
      runs.clear();
      for (const auto& sp : s) {
        const double dx = x - (sp.centre_m.x - m->reference.x);
        const double dy = y - (sp.centre_m.y - m->reference.y);
        const double hz2 = sp.radius_m * sp.radius_m - dx * dx - dy * dy;
        if (hz2 <= 0) continue;
        const double hz = std::sqrt(hz2);
        // Cell k has centre lo.z + (k + 0.5)h; keep centres with |z − z_c| < hz.
        const double zc = sp.centre_m.z - lo.z;
        const auto k0 = std::max<int64_t>(0, std::llround(std::floor((zc - hz) / h - 0.5)) + 1);
        const auto k1 =
            std::min<int64_t>(count[2] - 1, std::llround(std::ceil((zc + hz) / h - 0.5)) - 1);
        if (k1 >= k0) runs.emplace_back(k0, k1);
      }
      if (runs.empty()) continue;
      std::sort(runs.begin(), runs.end());
      double n_col = 0, z_sum = 0, z2_sum = 0;
      for (size_t r = 0; r < runs.size();) {
        int64_t a = runs[r].first, b = runs[r].second;
        for (++r; r < runs.size() && runs[r].first <= b + 1; ++r) b = std::max(b, runs[r].second);
        const double n = static_cast<double>(b - a + 1);
        const double zbar = 0.5 * (centre(2, a) + centre(2, b));
        n_col += n;
        z_sum += n * zbar;
        z2_sum += n * zbar * zbar + h * h * n * (n * n - 1) / 12.0;
      }
      cells += static_cast<int64_t>(n_col);
      first += Eigen::Vector3d(x * n_col, y * n_col, z_sum);
      second(0, 0) += x * x * n_col;
      second(1, 1) += y * y * n_col;
      second(2, 2) += z2_sum;
      second(0, 1) += x * y * n_col;
      second(0, 2) += x * z_sum;
      second(1, 2) += y * z_sum;
    }
  }
  second(1, 0) = second(0, 1);
  second(2, 0) = second(0, 2);
  second(2, 1) = second(1, 2);
  m->volume = cells * dv;
  m->first = first * dv;
  // Each cell is a uniform cube: its own second moment about its centre is dv·h²/12 per axis.
  m->second = second * dv + m->volume * h * h / 12.0 * Eigen::Matrix3d::Identity();
  m->samples = cells;
  return true;
}

Moments MonteCarlo(const std::vector<ClumpSphere>& s, const MassPropertiesOptions& o) {
  Vec3 lo, hi;
  BoundingBox(s, &lo, &hi);
  Moments m;
  m.reference = 0.5 * (lo + hi);
  const Vec3 half = 0.5 * (hi - lo);
  Rng rng(o.seed);
  int64_t inside = 0;
  for (int64_t p = 0; p < o.monte_carlo_points; ++p) {
    const Vec3 d{rng.Uniform(-half.x, half.x), rng.Uniform(-half.y, half.y),
                 rng.Uniform(-half.z, half.z)};
    const Vec3 x = m.reference + d;
    bool in = false;
    for (const auto& sp : s) {
      if (Norm2(x - sp.centre_m) < sp.radius_m * sp.radius_m) {
        in = true;
        break;
      }
    }
    if (!in) continue;
    ++inside;
    const Eigen::Vector3d e = E(d);
    m.first += e;
    m.second += e * e.transpose();
  }
  const double w = 8.0 * half.x * half.y * half.z / static_cast<double>(o.monte_carlo_points);
  m.volume = inside * w;
  m.first *= w;
  m.second *= w;
  m.samples = o.monte_carlo_points;
  return m;
}

}  // namespace

const char* MassMethodName(MassMethod method) {
  switch (method) {
    case MassMethod::kAuto:
      return "auto";
    case MassMethod::kExactSum:
      return "exact_sum";
    case MassMethod::kCollinear:
      return "collinear";
    case MassMethod::kVoxel:
      return "voxel";
    case MassMethod::kMonteCarlo:
      return "monte_carlo";
  }
  return "unknown";
}

bool MassPropertiesOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (voxel_divisions < 1) {
    os << "MassPropertiesOptions.voxel_divisions = " << voxel_divisions << " must be >= 1";
  } else if (max_voxel_columns < 1) {
    os << "MassPropertiesOptions.max_voxel_columns = " << max_voxel_columns << " must be >= 1";
  } else if (monte_carlo_points < 1000) {
    os << "MassPropertiesOptions.monte_carlo_points = " << monte_carlo_points << " must be >= 1000";
  } else {
    return true;
  }
  return Fail(error, os.str());
}

bool ComputeMassProperties(const std::vector<ClumpSphere>& spheres, double density_kg_m3,
                           const MassPropertiesOptions& options, MassProperties* out,
                           std::string* error) {
  if (!options.IsValid(error) || !ValidateSpheres(spheres, error)) return false;
  if (!std::isfinite(density_kg_m3) || density_kg_m3 <= 0) {
    std::ostringstream os;
    os << "clump: density_kg_m3 = " << density_kg_m3 << " must be finite and > 0";
    return Fail(error, os.str());
  }
  Vec3 origin, axis;
  const bool collinear = CollinearAxis(spheres, &origin, &axis);
  MassMethod method = options.method;
  if (method == MassMethod::kAuto) {
    method = !AnyOverlap(spheres) ? MassMethod::kExactSum
             : collinear          ? MassMethod::kCollinear
                                  : MassMethod::kVoxel;
  }
  Moments m;
  switch (method) {
    case MassMethod::kExactSum:
      m = ExactSum(spheres);
      break;
    case MassMethod::kCollinear:
      if (!collinear) return Fail(error, "clump: method collinear needs collinear centres");
      m = Collinear(spheres, origin, axis);
      break;
    case MassMethod::kVoxel:
      if (!Voxel(spheres, options, &m, error)) return false;
      break;
    case MassMethod::kMonteCarlo:
      m = MonteCarlo(spheres, options);
      break;
    case MassMethod::kAuto:
      break;  // resolved above
  }
  if (!(m.volume > 0)) {
    return Fail(error, std::string("clump: integrated volume is zero (method ") +
                           MassMethodName(method) + "); refine the integration");
  }
  // Shift the second moment to the centre of mass and convert to the inertia tensor.
  const Eigen::Vector3d c = m.first / m.volume;
  const Eigen::Matrix3d second_c = m.second - m.volume * c * c.transpose();
  out->volume_m3 = m.volume;
  out->mass_kg = density_kg_m3 * m.volume;
  out->centre_of_mass_m = m.reference + Vec3{c.x(), c.y(), c.z()};
  out->inertia_kg_m2 = density_kg_m3 * (second_c.trace() * Eigen::Matrix3d::Identity() - second_c);
  out->method_used = method;
  out->samples = m.samples;
  return true;
}

AspectRatios AspectRatiosFromExtents(const Vec3& extents_m) {
  std::array<double, 3> e = {extents_m.x, extents_m.y, extents_m.z};
  std::sort(e.begin(), e.end(), std::greater<>());
  return {e[1] / e[0], e[2] / e[1], e[0] / e[2]};
}

double ClumpTemplate::EquivalentVolumeDiameter() const { return std::cbrt(6.0 * volume_m3 / kPi); }

double ClumpTemplate::BoundingRadius() const {
  double r = 0;
  for (const auto& sp : spheres) r = std::max(r, Norm(sp.centre_m) + sp.radius_m);
  return r;
}

Vec3 ClumpTemplate::BoundingBoxExtents() const {
  if (spheres.empty()) return {};
  Vec3 lo, hi;
  BoundingBox(spheres, &lo, &hi);
  return hi - lo;
}

bool PrincipalFrame(const Eigen::Matrix3d& inertia, Vec3* moments, Eigen::Matrix3d* axes) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  if (eig.info() != Eigen::Success) return false;
  Eigen::Matrix3d r = eig.eigenvectors();
  for (int a = 0; a < 2; ++a) {
    Eigen::Index big;
    r.col(a).cwiseAbs().maxCoeff(&big);
    if (r(big, a) < 0) r.col(a) *= -1.0;
  }
  r.col(2) = r.col(0).cross(r.col(1));
  *moments = {eig.eigenvalues().x(), eig.eigenvalues().y(), eig.eigenvalues().z()};
  *axes = r;
  return true;
}

bool BuildClumpTemplate(const std::vector<ClumpSphere>& spheres, double density_kg_m3,
                        const MassPropertiesOptions& options, ClumpTemplate* out,
                        std::string* error) {
  MassProperties mp;
  if (!ComputeMassProperties(spheres, density_kg_m3, options, &mp, error)) return false;
  Vec3 moments;
  Eigen::Matrix3d r;
  if (!PrincipalFrame(mp.inertia_kg_m2, &moments, &r)) {
    return Fail(error, "clump: inertia diagonalisation failed");
  }
  ClumpTemplate t;
  t.density_kg_m3 = density_kg_m3;
  t.volume_m3 = mp.volume_m3;
  t.mass_kg = mp.mass_kg;
  t.principal_inertia_kg_m2 = moments;
  t.method_used = mp.method_used;
  t.input_centre_of_mass_m = mp.centre_of_mass_m;
  t.input_from_principal = FromRotationMatrix(r);
  for (const auto& sp : spheres) {
    const Eigen::Vector3d p = r.transpose() * E(sp.centre_m - mp.centre_of_mass_m);
    t.spheres.push_back({{p.x(), p.y(), p.z()}, sp.radius_m});
  }
  *out = std::move(t);
  return true;
}

}  // namespace demcal::core
