#include "workflow/reproduce/aspect_bounds.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "core/bodies/clump_shapes.h"

namespace demcal::workflow {
namespace {

// The chain of `count` spheres on [aspect, 1, 1]; false where the builder refuses it.
bool Chain(int count, double aspect, core::ShapeApproximation* shape) {
  std::string ignored;
  return core::ApproximateEllipsoid({aspect, 1, 1}, count, shape, &ignored);
}

// The largest x in [lo, hi] at which `holds` is true, for a predicate true at lo and false at hi
// (or the smallest, with `holds` false at lo and true at hi): 40 bisections, to 1e-12 of the
// range.
template <typename Predicate>
double Boundary(double lo, double hi, Predicate holds) {
  const bool at_lo = holds(lo);
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (holds(mid) == at_lo ? lo : hi) = mid;
  }
  return at_lo ? lo : hi;
}

}  // namespace

double MinMemberSpacing(int count, double aspect) {
  if (count < 2) return std::numeric_limits<double>::infinity();
  core::ShapeApproximation shape;
  if (!Chain(count, aspect, &shape)) return 0;
  std::vector<core::ClumpSphere> s = shape.spheres;  // centres on the x axis
  std::sort(s.begin(), s.end(), [](auto& p, auto& q) { return p.centre_m.x < q.centre_m.x; });
  double spacing = std::numeric_limits<double>::infinity();
  for (size_t k = 1; k < s.size(); ++k)
    spacing = std::min(spacing, (s[k].centre_m.x - s[k - 1].centre_m.x) /
                                    std::min(s[k].radius_m, s[k - 1].radius_m));
  return spacing;
}

double ConnectedAspectLimit(int count, double min, double max) {
  auto connected = [count](double aspect) {
    core::ShapeApproximation shape;
    return Chain(count, aspect, &shape) && shape.connected;
  };
  if (count < 2 || connected(max)) return max;
  if (!connected(min)) return min;
  return Boundary(min, max, connected);  // chains part as they stretch
}

double DistinctAspectLimit(int count, double min, double max) {
  auto distinct = [count](double aspect) {
    return MinMemberSpacing(count, aspect) >= kMinMemberSpacing;
  };
  if (count < 2 || distinct(min)) return min;
  if (!distinct(max)) return max;
  return Boundary(min, max, distinct);  // the spheres draw apart as the chain stretches
}

}  // namespace demcal::workflow
